// The span request checked once: its names parsed into the span layer's enums, each
// bad setting refused by name, the checks that need the span apart.

#include <string>

#include <gtest/gtest.h>

#include "stockbridge/core/error.hpp"
#include "stockbridge/io/span_file.hpp"
#include "stockbridge/requests/span_request.hpp"
#include "support/error_message.hpp"

namespace stockbridge::requests {
namespace {

TEST(CheckedSpanRequest, ParsesTheNamesIntoTheBalancesTypesOnce) {
  SpanRequest request;
  request.damper_model = "weak";
  request.position_min = 0.5;
  request.position_max = 3.0;
  request.spacing_min = 0.7;
  request.objective = "life";
  const CheckedSpanRequest checked = check_span_request(request);
  ASSERT_TRUE(checked.damper_model().has_value());
  EXPECT_EQ(*checked.damper_model(), span::DamperModel::weak);
  ASSERT_TRUE(checked.positions().has_value());
  EXPECT_EQ(checked.positions()->objective, span::PositionObjective::life);
  EXPECT_EQ(checked.positions()->position_min, 0.5);
  EXPECT_EQ(checked.positions()->position_max, 3.0);
  EXPECT_EQ(checked.positions()->spacing_min, 0.7);

  const CheckedSpanRequest plain = check_span_request(SpanRequest{});
  EXPECT_FALSE(plain.damper_model().has_value());
  EXPECT_FALSE(plain.positions().has_value());
}

TEST(CheckedSpanRequest, EachBadSettingIsRefusedByItsName) {
  const auto refused = [](auto change) {
    SpanRequest request;
    change(request);
    return testing::invalid_parameter_message([&] { check_span_request(request); });
  };
  EXPECT_NE(refused([](SpanRequest& r) { r.damper_model = "slow"; }).find("damper_model = 'slow'"), std::string::npos);
  EXPECT_NE(refused([](SpanRequest& r) { r.objective = "cost"; }).find("objective = \"cost\""), std::string::npos);
  EXPECT_NE(refused([](SpanRequest& r) { r.points = 1; }).find("points"), std::string::npos);
  EXPECT_NE(refused([](SpanRequest& r) { r.threads = 0; }).find("threads"), std::string::npos);
  EXPECT_NE(refused([](SpanRequest& r) { r.position_min = 0.5; }).find("optimize_position"), std::string::npos);
  EXPECT_NE(refused([](SpanRequest& r) {
              r.position_min = 3.0;
              r.position_max = 0.5;
            }).find("optimize_position = 3:0.5"),
            std::string::npos);
}

TEST(CheckedSpanRequest, TheSpansChecksComeApart) {
  const io::SpanFile file = io::load_span_file(std::string(STOCKBRIDGE_SOURCE_DIR) + "/examples/aster570_400m.toml");
  SpanRequest request;
  request.position_min = 0.5;
  request.position_max = 3.0;
  request.objective = "life";
  const CheckedSpanRequest checked = check_span_request(request);
  EXPECT_NO_THROW(check_against_span(checked, file.span));  // the example has a climate and a damper
  EXPECT_NE(testing::invalid_parameter_message([&] { check_against_span(checked, file.span.without_dampers()); })
                .find("optimize_position: the span file has no [[damper]] to place"),
            std::string::npos);
}

}  // namespace
}  // namespace stockbridge::requests
