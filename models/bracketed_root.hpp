#pragma once
/// The one bracketed scalar root finder of the project: the Illinois variant of
/// regula falsi (Dowell & Jarratt 1971). Superlinear, exact on a linear piece of
/// f, and never leaves its bracket, which is why the rigid penetrometer's contact
/// velocity uses it, and the SSMC's softening return takes the same steps one
/// evaluation at a time (strain_softening_return.cpp, to interleave points).
#include <cmath>

namespace ffp {

struct BracketedRoot {
  double x = 0.0;  ///< the last iterate
  double f = 0.0;  ///< f(x): the last evaluation of f was at x
  bool converged = false;
};

/// A root of f between `newest` and `other`, whose values f_newest and f_other
/// have opposite signs. Each step draws the secant through the two ends; the new
/// point replaces `newest`, and `other` becomes the old `newest` when f changes
/// sign, else keeps its place with its value halved (the Illinois step).
/// Stops when |f(x)| ≤ tolerance_f, or when the bracket is no wider than
/// tolerance_x(x) (a callable: the width may be relative to the iterate), or
/// after max_iterations. f is evaluated only at the iterates, and last at the
/// returned x, so a caller may keep what f computed alongside.
template <class F, class Width>
BracketedRoot illinois_root(F&& f, double newest, double f_newest, double other, double f_other, double tolerance_f,
                            Width&& tolerance_x, int max_iterations) {
  BracketedRoot root{newest, f_newest, std::abs(f_newest) <= tolerance_f};
  for (int iteration = 0; iteration < max_iterations && !root.converged; ++iteration) {
    const double next = newest - f_newest * (newest - other) / (f_newest - f_other);
    const double f_next = f(next);
    if ((f_next > 0.0) != (f_newest > 0.0)) {
      other = newest;
      f_other = f_newest;
    } else {
      f_other *= 0.5;
    }
    newest = next;
    f_newest = f_next;
    root = {next, f_next, std::abs(f_next) <= tolerance_f || std::abs(newest - other) <= tolerance_x(next)};
  }
  return root;
}

}  // namespace ffp
