#pragma once
/// A small Markdown document builder for the validation report.
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace ffp {

class Markdown {
 public:
  void heading(int level, const std::string& text);
  void paragraph(const std::string& text);
  void table(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows);
  /// An image; `png` is made relative to the document's folder by the caller.
  void figure(const std::string& relative_png, const std::string& caption);
  void raw(const std::string& text) { out_ << text; }
  std::string str() const { return out_.str(); }

 private:
  std::ostringstream out_;
};

/// "%.3g"-style formatting helpers for tables.
std::string fixed(double value, int decimals);
std::string percent_difference(double ours, double reference);

}  // namespace ffp
