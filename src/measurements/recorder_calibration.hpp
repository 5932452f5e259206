#pragma once
// The calibration of span parameters on a recorder's counts (recorder_calibration.cpp),
// which analyse_record runs after its prediction.

#include "stockbridge/measurements/recorder.hpp"

namespace stockbridge::measurements {

/// The parameters of options.calibrate fitted so that the span's predicted mean
/// ln Yb per band meets the recorded one, from the prediction `before`.
RecorderCalibration calibrate_record(const RecorderCounts& counts, const span::Span& span,
                                     const span::SpanTables& tables, const span::BalanceOptions& balance,
                                     const RecorderOptions& options, const RecorderPrediction& before);

}  // namespace stockbridge::measurements
