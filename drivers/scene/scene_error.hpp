#pragma once
#include <stdexcept>
#include <string>

namespace ffp {

/// Bad input: the message is one line naming the JSON path (or file, or CSV
/// cell) and what is allowed. The program prints it and exits with code 2.
class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace ffp
