#pragma once
/// The one bracketed scalar root finder of the project: the Illinois variant of
/// regula falsi (Dowell & Jarratt 1971). Superlinear, exact on a linear piece of
/// f, and never leaves its bracket, which is why the rigid penetrometer's contact
/// velocity uses it, and the SSMC's softening return takes its steps
/// (IllinoisBracket) one evaluation at a time (strain_softening_return.cpp, to
/// interleave points).
#include <cmath>

namespace ffp {

struct BracketedRoot {
  double x = 0.0;  ///< the last iterate
  double f = 0.0;  ///< f(x): the last evaluation of f was at x
  bool converged = false;
};

/// The bracket of the Illinois variant of regula falsi: the last iterate `newest` and
/// the end `other` across the root, with their values of f.
struct IllinoisBracket {
  double newest = 0.0, f_newest = 0.0, other = 0.0, f_other = 0.0;

  /// The zero of the secant through the two ends: the next iterate.
  double secant() const { return newest - f_newest * (newest - other) / (f_newest - f_other); }
  /// The new iterate x replaces `newest`; `other` becomes the old `newest` when f
  /// changes sign, else keeps its place with its value halved (the Illinois step).
  void take(double x, double f_x) {
    if ((f_x > 0.0) != (f_newest > 0.0)) {
      other = newest;
      f_other = f_newest;
    } else {
      f_other *= 0.5;
    }
    newest = x;
    f_newest = f_x;
  }
};

/// A root of f between `newest` and `other`, whose values f_newest and f_other
/// have opposite signs, by IllinoisBracket's steps.
/// Stops when |f(x)| ≤ tolerance_f, or when the bracket is no wider than
/// tolerance_x(x) (a callable: the width may be relative to the iterate), or
/// after max_iterations. f is evaluated only at the iterates, and last at the
/// returned x, so a caller may keep what f computed alongside.
template <class F, class Width>
BracketedRoot illinois_root(F&& f, double newest, double f_newest, double other, double f_other, double tolerance_f,
                            Width&& tolerance_x, int max_iterations) {
  IllinoisBracket b{newest, f_newest, other, f_other};
  BracketedRoot root{newest, f_newest, std::abs(f_newest) <= tolerance_f};
  for (int iteration = 0; iteration < max_iterations && !root.converged; ++iteration) {
    const double next = b.secant();
    b.take(next, f(next));
    root = {b.newest, b.f_newest,
            std::abs(b.f_newest) <= tolerance_f || std::abs(b.newest - b.other) <= tolerance_x(b.newest)};
  }
  return root;
}

}  // namespace ffp
