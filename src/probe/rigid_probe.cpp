// rigid_probe.cpp - the rigid-body probes of the body made of the probe's (rigid) material (sim/rigid_bodies.h):
// "rigid_position" and "rigid_velocity", its centre of mass and that point's velocity (dim columns <name>_x,
// <name>_y(, <name>_z)), and "rigid_angle", its rotation from the untilted shape [rad] (2D: counter-clockwise,
// not wrapped; 3D: the rotation's angle). Scene key: material (required: a rigid material that a body is made of).
#include "probe/probe.h"

namespace cdmpm {
namespace {

enum class Quantity { Position, Velocity, Angle };

template <int dim>
class RigidProbe final : public Probe<dim> {
 public:
  RigidProbe(const SceneReader& r, const Node& n, const Scene& scene, Quantity what)
      : Probe<dim>(r, n, scene, {"material"}), what_(what) {
    Node mat = r.required(n, "material");
    if (!scene.materials[this->material_index_].traits().rigid) r.expected(mat, "the name of a rigid material");
    bool used = false;
    for (const auto& b : scene.bodies) used = used || b.material_index == this->material_index_;
    if (!used) r.expected(mat, "a rigid material that a body is made of");
  }
  Strings columns() const override {
    if (what_ == Quantity::Angle) return {this->name_};
    Strings c;
    for (int a = 0; a < dim; ++a) c.push_back(this->name_ + "_" + "xyz"[a]);
    return c;
  }
  void sample(const Simulation<dim>& sim, std::vector<double>& out) const override {
    const RigidBody<dim>& b = sim.rigid.bodies[sim.rigid.index_of_material(this->material_index_)];
    if (what_ == Quantity::Angle) out.push_back(b.angle);
    for (int a = 0; a < dim && what_ == Quantity::Position; ++a) out.push_back(b.centre[a]);
    for (int a = 0; a < dim && what_ == Quantity::Velocity; ++a) out.push_back(b.velocity[a]);
  }

 private:
  Quantity what_;
};

}  // namespace

CDMPM_PROBE_FACTORY(make_rigid_position, RigidProbe, Quantity::Position)
CDMPM_PROBE_FACTORY(make_rigid_velocity, RigidProbe, Quantity::Velocity)
CDMPM_PROBE_FACTORY(make_rigid_angle, RigidProbe, Quantity::Angle)

}  // namespace cdmpm
