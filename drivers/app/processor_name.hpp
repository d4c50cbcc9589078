#pragma once
/// The processor a timing was taken on, for `ffp bench`'s header and the report's: times mean
/// little without the machine (the same build runs 1.5–2 × apart on two EPYCs).
#include <istream>
#include <string>

namespace ffp {

/// The first "model name" of a /proc/cpuinfo text, spaces trimmed; "unknown
/// processor" when there is none (another system, or a text without it).
std::string processor_name(std::istream& cpuinfo);
/// processor_name of this machine's /proc/cpuinfo.
std::string this_processor();

}  // namespace ffp
