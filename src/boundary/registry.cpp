// registry.cpp - the boundary registry: the scene "type" of each boundary and the function that builds it
// (one file per type). Adding a boundary type: its file, and one line in kRegistry below (and docs/scenes.md).
#include <map>

#include "boundary/boundary.h"

namespace cdmpm {

template <int dim>
using BoundaryFactory = std::unique_ptr<Boundary<dim>> (*)(const SceneReader&, const Node&, const BoundaryContext<dim>&);

template <int dim> std::unique_ptr<Boundary<dim>> make_walls(const SceneReader&, const Node&, const BoundaryContext<dim>&);
template <int dim> std::unique_ptr<Boundary<dim>> make_half_plane(const SceneReader&, const Node&, const BoundaryContext<dim>&);
template <int dim> std::unique_ptr<Boundary<dim>> make_box_obstacle(const SceneReader&, const Node&, const BoundaryContext<dim>&);
template <int dim> std::unique_ptr<Boundary<dim>> make_bathymetry(const SceneReader&, const Node&, const BoundaryContext<dim>&);
template <int dim> std::unique_ptr<Boundary<dim>> make_absorbing_layer(const SceneReader&, const Node&, const BoundaryContext<dim>&);

namespace {

struct Entry {
  const char* type;
  BoundaryFactory<2> make2;
  BoundaryFactory<3> make3;
};
#define CDMPM_BOUNDARY(name, factory) Entry{name, factory<2>, factory<3>}
const Entry kRegistry[] = {
    CDMPM_BOUNDARY("walls", make_walls),
    CDMPM_BOUNDARY("half_plane", make_half_plane),
    CDMPM_BOUNDARY("box", make_box_obstacle),
    CDMPM_BOUNDARY("bathymetry", make_bathymetry),
    CDMPM_BOUNDARY("absorbing_layer", make_absorbing_layer),
};
#undef CDMPM_BOUNDARY

}  // namespace

Strings boundary_types() {
  Strings out;
  for (const Entry& e : kRegistry) out.push_back(e.type);
  return out;
}

template <int dim>
Boundary<dim>::Boundary(const SceneReader& r, const Node& n, Real dx) : tol_(node_tolerance(dx)) {
  const std::string c = n.has("condition") ? r.string(n["condition"], {"sticky", "slip", "separate"}) : "separate";
  condition_ = c == "sticky" ? BoundaryCondition::Sticky : c == "slip" ? BoundaryCondition::Slip : BoundaryCondition::Separate;
  friction_ = static_cast<Real>(r.number(n, "friction", ge(0), 0.0));
}

template <int dim>
std::unique_ptr<Boundary<dim>> make_boundary(const SceneReader& r, const Node& n, const BoundaryContext<dim>& ctx) {
  if (!n.j.is_object()) r.expected(n, "an object");
  const std::string type = r.string(r.required(n, "type"), boundary_types());
  for (const Entry& e : kRegistry)
    if (type == e.type) {
      if constexpr (dim == 2) return e.make2(r, n, ctx);
      else return e.make3(r, n, ctx);
    }
  r.expected(n["type"], "a registered boundary type");  // not reached: string() checked the choice
}

template <int dim>
std::unique_ptr<Boundary<dim>> make_boundary(const Scene& scene, const BoundarySpec& spec, const BoundaryContext<dim>& ctx) {
  SceneReader r(scene.path, dim);
  r.set_domain(scene.domain.size);
  return make_boundary<dim>(r, Node{spec.json, spec.path}, ctx);
}

template class Boundary<2>;
template class Boundary<3>;
template std::unique_ptr<Boundary<2>> make_boundary<2>(const SceneReader&, const Node&, const BoundaryContext<2>&);
template std::unique_ptr<Boundary<3>> make_boundary<3>(const SceneReader&, const Node&, const BoundaryContext<3>&);
template std::unique_ptr<Boundary<2>> make_boundary<2>(const Scene&, const BoundarySpec&, const BoundaryContext<2>&);
template std::unique_ptr<Boundary<3>> make_boundary<3>(const Scene&, const BoundarySpec&, const BoundaryContext<3>&);

}  // namespace cdmpm
