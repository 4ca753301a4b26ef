// CSV fields as RFC 4180 writes them, for every table coremodal writes
// (converge.csv, study.csv, calibration.csv, batch.csv).
#pragma once

#include <string>

namespace coremodal {

// `text` as one CSV field: unchanged unless it holds a comma, a double quote
// or a line break (CR or LF); then in double quotes, with every double quote
// doubled. A line break stays inside the quotes (RFC 4180, section 2.6).
std::string csv_field(const std::string& text);

}  // namespace coremodal
