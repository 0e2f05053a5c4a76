// flip_share.h - the material keys of the FLIP share of the velocity update (transfer/flip.h):
//   flip  a in [0, 1], the share of FLIP (0: APIC unchanged);
//   xpic  m in [1, 8], the order of the extended-PIC filter of that share (Hammerquist & Nairn 2017, "A new
//         method for material point method particle updates that reduces noise and enhances stability",
//         CMAME 318): the FLIP share keeps only the part of the particle velocity that the grid's consistent
//         mass matrix represents, to order m; 0 (the default) keeps all of it (plain FLIP). Needs flip > 0.
// Read by the materials that take the keys (water.h, rigid.h, ice.h).
#pragma once

#include "core/types.h"
#include "scene/scene_reader.h"

namespace cdmpm {

struct FlipShare {
  Real a = 0;    // the FLIP share
  int xpic = 0;  // the XPIC order of that share (0: plain FLIP)
};

inline FlipShare read_flip_share(const SceneReader& r, const Node& n) {
  FlipShare f;
  f.a = static_cast<Real>(r.number(n, "flip", {0, 1}, 0.0));
  if (n.has("xpic")) {
    f.xpic = r.integer(n["xpic"], {1, 8});
    if (f.a == 0) r.fail(n.child("xpic"), "needs \"flip\" > 0 (xpic filters the FLIP share of the velocity update)");
  }
  return f;
}

}  // namespace cdmpm
