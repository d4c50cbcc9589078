#pragma once
/// What a law's update did at a point: stayed elastic, or returned to which
/// part of the yield surface. A law without a yield surface always reports
/// `elastic`.

namespace ffp {

/// Which part of the yield surface a return mapping ended on.
enum class ReturnRegion : unsigned char { elastic, plane, edge_compression, edge_extension, apex };

}  // namespace ffp
