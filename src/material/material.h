// material.h - the material registry and table: one constitutive model per named scene material.
//
// The models (one file each, material/material_model.h says what each provides) are the alternatives of
// MaterialModel, a std::variant: dispatch in the hot loops is static (a switch on the variant's index, no
// virtual call), and a material of an unknown type cannot exist past the loader, which only builds the
// alternatives listed here. Adding a model: its file, and one entry in the variant below (and its keys in
// docs/scenes.md). Each particle stores an index into the scene's table of Materials (core/particles.h).
#pragma once

#include <string>
#include <variant>

#include "material/ice.h"
#include "material/material_model.h"
#include "material/rigid.h"
#include "material/water.h"

namespace cdmpm {

// The registry: every constitutive model the scene "type" key may name.
using MaterialModel = std::variant<Water, Ice, Rigid>;

template <class... M>
constexpr bool all_models(std::variant<M...>*) { return (ConstitutiveModel<M> && ...); }
static_assert(all_models(static_cast<MaterialModel*>(nullptr)), "every registered material model is a ConstitutiveModel");

struct Material {
  std::string name;
  MaterialModel model;
  Real half_spacing = 0;  // half the particle spacing of this material's bodies (set by seeding; surface probes)

  // f(model) with the model's concrete type.
  template <class F>
  decltype(auto) visit(F&& f) const { return std::visit(std::forward<F>(f), model); }
  const MaterialTraits& traits() const {
    return visit([](const auto& m) -> const MaterialTraits& { return std::decay_t<decltype(m)>::traits; });
  }
  std::string_view type() const { return visit([](const auto& m) { return std::decay_t<decltype(m)>::type; }); }
  Real density() const { return visit([](const auto& m) { return m.density(); }); }
  // The options against the one-field drag (docs/water.md, "Buoyancy: J-bar and FLIP"): j_bar of water and
  // rigid materials, flip of water, rigid and ice; false and 0 for a model without the key.
  bool j_bar() const {
    return visit([](const auto& m) { if constexpr (requires { m.j_bar; }) return m.j_bar; else return false; });
  }
  Real flip() const {
    return visit([](const auto& m) -> Real { if constexpr (requires { m.flip; }) return m.flip.a; else return Real(0); });
  }
  // A body in a velocity field of its own, in frictionless contact with the others: a rigid body's field
  // (sim/rigid_contact.h) or the deformable solids' field (ice; sim/field_contact.h). Such particles are left out
  // of the shared field's p2g (transfer/p2g.h).
  bool contact() const {
    return visit([](const auto& m) { if constexpr (requires { m.contact; }) return m.contact; else return false; });
  }
  // Water's `continuity` "interpolated": g2p sets tr C_p to the divergence of the interpolated velocity
  // (transfer/g2p.h); false for the other models.
  bool interpolated_divergence() const {
    return visit([](const auto& m) {
      if constexpr (requires { m.interpolated_divergence; }) return m.interpolated_divergence; else return false;
    });
  }
  // The XPIC order of the FLIP share (transfer/flip.h); 0: plain FLIP, or no FLIP share.
  int xpic() const {
    return visit([](const auto& m) -> int { if constexpr (requires { m.flip; }) return m.flip.xpic; else return 0; });
  }
};

// Reads the material `name` from its scene object (its "type" names a registered model, which reads the rest).
Material parse_material(const SceneReader& reader, const Node& node, const std::string& name);

// Reference (unstressed) volume V0 = m / rho0 of a particle of mass m (seeding sets m = rho0 V0).
inline Real reference_volume(const Material& m, Real mass) { return mass / m.density(); }

}  // namespace cdmpm
