// frame_writer.cpp - a simulation's particles as a .vtu frame (frame_writer.h).
#include "io/frame_writer.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "io/vtu_writer.h"
#include "material/stress.h"

namespace cdmpm {
namespace {

// The materials' extra field names, each once, in the order of the material table; and for every material,
// the column of each of its fields in that list.
struct ExtraFields {
  Strings names;
  std::vector<std::vector<int>> column;  // per material
  explicit ExtraFields(const std::vector<Material>& materials) {
    for (const Material& m : materials) {
      column.emplace_back();
      for (const std::string& f : m.visit([](const auto& model) { return model.field_names(); })) {
        auto it = std::find(names.begin(), names.end(), f);
        if (it == names.end()) it = names.insert(names.end(), f);
        column.back().push_back(static_cast<int>(it - names.begin()));
      }
      if (column.back().size() > max_per_material) throw std::logic_error("a material model has more than 16 output fields");
    }
  }
  static constexpr size_t max_per_material = 16;
};

// The frame's positions, point fields and options.
template <int dim>
void frame_data(const Simulation<dim>& sim, std::vector<double>& pts, std::vector<VtuField>& fields, VtuOptions& options) {
  const auto& P = sim.particles;
  const size_t n = P.size();
  pts.assign(3 * n, 0.0);
  VtuField vel{"velocity", 3, std::vector<float>(3 * n, 0.f), {}, {}};
  VtuField mat{"material", 1, {}, {}, std::vector<int32_t>(P.material.begin(), P.material.end())};
  VtuField pres{"pressure", 1, std::vector<float>(n), {}, {}};
  VtuField J{"J", 1, std::vector<float>(n), {}, {}};
  VtuField stress{"stress", 9, std::vector<float>(9 * n, 0.f), {}, {}};
  VtuField id{"id", 1, {}, {}, {}, std::vector<int64_t>(P.id.begin(), P.id.end())};
  VtuField mass{"mass", 1, std::vector<float>(n), {}, {}};
  VtuField volume{"volume", 1, std::vector<float>(n), {}, {}};
  const ExtraFields extra(sim.materials);
  std::vector<VtuField> more;
  // A field of some materials only (damage, alpha, p0 of ice) is NaN on the particles of the others, so water
  // is not mistaken for intact ice when a frame is coloured by damage (ParaView draws NaN in its NaN colour).
  constexpr float absent = std::numeric_limits<float>::quiet_NaN();
  for (const std::string& name : extra.names) more.push_back({name, 1, std::vector<float>(n, absent), {}, {}});
#pragma omp parallel for schedule(static)
  for (size_t q = 0; q < n; ++q) {
    const Material& m = sim.materials[P.material[q]];
    for (int a = 0; a < dim; ++a) {
      pts[3 * q + a] = P.x[q][a];
      vel.f32[3 * q + a] = static_cast<float>(P.v[q][a]);
    }
    pres.f32[q] = static_cast<float>(particle_pressure(m, P, q));
    J.f32[q] = static_cast<float>(P.J[q]);
    mass.f32[q] = static_cast<float>(P.mass[q]);
    volume.f32[q] = static_cast<float>(reference_volume(m, P.mass[q]) * P.J[q]);
    const Mat<dim> sigma = cauchy_stress(m, P, q);
    for (int a = 0; a < dim; ++a)
      for (int b = 0; b < dim; ++b) stress.f32[9 * q + 3 * a + b] = static_cast<float>(sigma(a, b));
    const std::vector<int>& cols = extra.column[P.material[q]];
    if (cols.empty()) continue;
    float values[ExtraFields::max_per_material] = {};
    m.visit([&](const auto& model) { model.template fields<dim>(P, q, values); });
    for (size_t k = 0; k < cols.size(); ++k) more[cols[k]].f32[q] = values[k];
  }
  // Moved, not copied: a frame's fields are the largest buffers of an output step.
  fields.clear();
  for (VtuField* f : {&vel, &mat, &pres, &J, &stress, &id, &mass, &volume}) fields.push_back(std::move(*f));
  for (VtuField& f : more) fields.push_back(std::move(f));
  options.compression = sim.scene.output.compress ? VtuCompression::ZLib : VtuCompression::None;
  options.positions = sim.scene.output.float32_positions ? VtuReal::Float32 : VtuReal::Float64;
  options.time = sim.time();
  VtuStrings names{kVtuMaterialNames, {}};
  for (const Material& mt : sim.materials) names.values.push_back(mt.name);
  options.metadata = {names};
}

}  // namespace

template <int dim>
void write_frame(const std::string& path, const Simulation<dim>& sim) {
  std::vector<double> pts;
  std::vector<VtuField> fields;
  VtuOptions options;
  frame_data(sim, pts, fields, options);
  write_vtu(path, pts, fields, options);
}

template <int dim>
void write_frame_piece(const std::string& piece, const Simulation<dim>& sim, const std::string& pvtu,
                       const std::vector<std::string>& pieces) {
  std::vector<double> pts;
  std::vector<VtuField> fields;
  VtuOptions options;
  frame_data(sim, pts, fields, options);
  // The arrays' names and types for the .pvtu, also when this rank's piece is empty: one value of the type each.
  std::vector<VtuField> types;
  for (const VtuField& f : fields) {
    VtuField t{f.name, f.components, {}, {}, {}};
    if (f.name == "material") t.i32 = {0};
    else if (f.name == "id") t.i64 = {0};
    else t.f32 = {0.f};
    types.push_back(std::move(t));
  }
  write_vtu(piece, pts, fields, options);
  if (!pvtu.empty()) write_pvtu(pvtu, pieces, types, options);
}

template void write_frame<2>(const std::string&, const Simulation<2>&);
template void write_frame<3>(const std::string&, const Simulation<3>&);
template void write_frame_piece<2>(const std::string&, const Simulation<2>&, const std::string&,
                                   const std::vector<std::string>&);
template void write_frame_piece<3>(const std::string&, const Simulation<3>&, const std::string&,
                                   const std::vector<std::string>&);

}  // namespace cdmpm
