#pragma once
// The report of `stockbridge fatigue-tests --report`: the tests, the censored
// Basquin fit and its design curve, the failures below the Safe Border Line, and the
// S-N plot (failures as dots, runouts as rings, the fit, the design curve and the
// Safe Border Line of each layer count present), then the table of the tests.

#include <string>

#include "stockbridge/report/reports.hpp"
#include "stockbridge/requests/fatigue_tests_request.hpp"

namespace stockbridge::report {

std::string fatigue_tests_report(const requests::FatigueTestsOutcome& outcome, const ReportContext& context);

}  // namespace stockbridge::report
