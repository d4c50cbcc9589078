#include "reports/markdown.hpp"

#include <cmath>
#include <cstdio>

namespace ffp {

void Markdown::heading(int level, const std::string& text) {
  out_ << "\n" << std::string(static_cast<std::size_t>(level), '#') << " " << text << "\n\n";
}

void Markdown::paragraph(const std::string& text) { out_ << text << "\n\n"; }

void Markdown::table(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows) {
  out_ << "|";
  for (const auto& h : header) out_ << " " << h << " |";
  out_ << "\n|";
  for (std::size_t i = 0; i < header.size(); ++i) out_ << "---|";
  out_ << "\n";
  for (const auto& row : rows) {
    out_ << "|";
    for (const auto& cell : row) out_ << " " << cell << " |";
    out_ << "\n";
  }
  out_ << "\n";
}

void Markdown::figure(const std::string& relative_png, const std::string& caption) {
  out_ << "![" << caption << "](" << relative_png << ")\n\n*" << caption << "*\n\n";
}

std::string fixed(double value, int decimals) {
  if (!std::isfinite(value)) return "–";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
  return buffer;
}

std::string percent_difference(double ours, double reference) {
  if (!std::isfinite(ours) || !std::isfinite(reference) || reference == 0.0) return "–";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%+.0f %%", 100.0 * (ours - reference) / std::abs(reference));
  return buffer;
}

}  // namespace ffp
