// seeding.cpp - filling the bodies with particles (seeding.h).
#include "sim/seeding.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>

#include "boundary/mirror.h"
#include "scene/scene_reader.h"
#include "sim/rigid_bodies.h"

namespace cdmpm {
namespace {

template <int dim>
using DVec = Eigen::Matrix<double, dim, 1>;

// A wall face that lies between two grid planes. The wall acts on the grid nodes on or beyond it
// (boundary/walls.cpp) while particles are held at the face itself (keep_inside): material seeded within a cell of
// it flows out of the grid's reach and piles up on the face with no pressure (a 3D channel 750 m wide at dx = 20 m
// lost 2 m of its water level in 40 s). Seeding refuses that; a face no material touches (a lid) may lie anywhere.
struct OffGridFace {
  int axis;
  double position, cells;  // the face's coordinate [m] and that in cells
  std::string where, name;  // its path in the scene ("boundaries[0].faces[1]") and its name ("y+")
};

// The run through the scene's particles in seeding order: how many so far, and which this process keeps; the
// off-grid wall faces and the first body (its path) seeded within a cell of one, checked before `keep` so that
// every process of a distributed run finds the same.
template <int dim>
struct Seeding {
  const SeedFilter<dim>& keep;
  uint64_t seeded = 0;
  std::vector<OffGridFace> off_grid = {};
  const OffGridFace* touched = nullptr;
  std::string toucher = {};
};

// The "+" faces that the scene's boundaries close (Boundary::closed_faces: the walls') and that are not on a grid
// plane; the "-" faces are at 0. `boundaries` are built from scene.boundaries in order.
template <int dim>
std::vector<OffGridFace> off_grid_wall_faces(const Scene& scene, const std::vector<std::unique_ptr<Boundary<dim>>>& boundaries) {
  std::vector<OffGridFace> faces;
  for (size_t i = 0; i < boundaries.size(); ++i) {
    const Strings closed = boundaries[i]->closed_faces();
    const BoundarySpec& spec = scene.boundaries[i];
    for (size_t k = 0; k < closed.size(); ++k) {
      const std::string& name = closed[k];
      if (name[1] != '+') continue;
      const int a = name[0] - 'x';
      const double cells = scene.domain.size[a] / scene.domain.dx;
      int index = 0;
      if (on_grid_plane(static_cast<Real>(cells), index)) continue;
      // A listed face is named by its entry, the default (all faces) by the boundary.
      const std::string where = spec.path + (spec.json.contains("faces") ? ".faces[" + std::to_string(k) + "]" : "");
      faces.push_back({a, scene.domain.size[a], cells, where, name});
    }
  }
  return faces;
}

// A rigid body's shape turned by its tilt about its hinge (or centre); a replayed source's (rigid key `track`), the
// part of its shape that the recorded ice filled at t = 0 (io/source_track.h).
template <int dim>
struct Tilted {
  const Shape* shape;
  const SourceTrack* track;
  Mat<dim> R;
  Vec<dim> pivot;
  explicit Tilted(const BodySpec& b) : shape(&b.shape), track(b.track.get()), R(RigidAlgebra<dim>::tilt(b.tilt)) {
    for (int a = 0; a < dim; ++a)
      pivot[a] = static_cast<Real>(b.hinge.empty() ? 0.5 * (shape->lower(a) + shape->upper(a)) : b.hinge[a]);
  }
  bool contains(const DVec<dim>& x) const {
    const Vec<dim> u = pivot + R.transpose() * (x.template cast<Real>() - pivot);
    return shape->contains(u.template cast<double>()) && (!track || track->occupied(x[0], x[vertical_axis<dim>]));
  }
};

// One body's seeding: which lattice points it fills, and the particle it puts at each. With `crevasse_water`,
// the water standing in the crevasses of an ice body instead (shape/crevasse_field.h): the lattice points its
// crevasses cut up to their water level, as particles of the water material.
template <int dim>
class BodySeeder {
 public:
  BodySeeder(const Scene& scene, const BodySpec& body, const std::vector<Material>& materials,
             const std::vector<std::unique_ptr<Boundary<dim>>>& boundaries, Seeding<dim>& seeding,
             bool crevasse_water = false)
      : scene_(scene),
        body_(body),
        crevasse_water_(crevasse_water),
        material_index_(crevasse_water ? body.crevasses->water_material_index : body.material_index),
        mat_(materials[material_index_]),
        boundaries_(boundaries),
        seeding_(seeding),
        self_(body) {
    n_ = static_cast<int>(std::lround(std::pow(body.particles_per_cell, 1.0 / dim)));
    h_ = scene.domain.dx / n_;
    // A liquid's free surface is its still level: the lattice's layers are shifted down (by less than a spacing)
    // so that a layer's upper edge lies on the body's level (the solitary wave's still level, surface_level, or the
    // shape's top), where the wave gauges measure the water's top; the lowest layer then keeps the part of its
    // volume above the shape's bottom (seed_column). A level on a lattice plane keeps the lattice of the grid.
    if (mat_.traits().fluid && !mat_.traits().rigid && !crevasse_water) {
      constexpr int up = vertical_axis<dim>;
      const double level = body.liquid_level(up);
      const double planes = level / h_;
      if (std::abs(planes - std::round(planes)) > 1e-9 * std::max(1.0, std::abs(planes)))
        shift_ = level - std::ceil(planes) * h_;
    }
    if (!mat_.traits().rigid)
      for (const BodySpec& b : scene.bodies)
        if (materials[b.material_index].traits().rigid) rigid_shapes_.emplace_back(b);
    for (int a = 0; a < dim; ++a) {
      const double shift = a == vertical_axis<dim> ? shift_ : 0.0;
      lo_[a] = static_cast<int>(std::floor((body.shape.lower(a) - shift) / h_ - 0.5));
      hi_[a] = static_cast<int>(std::ceil((body.shape.upper(a) - shift) / h_ - 0.5));
      centre_[a] = static_cast<Real>(0.5 * (body.shape.lower(a) + body.shape.upper(a)));
      v0_[a] = body.velocity.empty() ? Real(0) : static_cast<Real>(body.velocity[a]);
    }
    G_.setZero();
    if (!body.velocity_gradient.empty())
      for (int r = 0; r < dim; ++r)
        for (int c = 0; c < dim; ++c) G_(r, c) = static_cast<Real>(body.velocity_gradient[r * dim + c]);
    cell_volume_ = static_cast<Real>(std::pow(h_, dim));
  }
  double spacing() const { return h_; }

  // Lattice columns along the vertical axis (the last), one at a time, so each column's top is known.
  // Fluid bodies also fill the bed layers of the boundaries (sim/bed_layer.h) into `bed`, if given.
  void seed(Particles<dim>& particles, BedLayer<dim>* bed) const {
    constexpr int up = vertical_axis<dim>;
    IVec<dim> k = lo_;
    std::vector<DVec<dim>> column, bed_column;
    std::vector<Vec<dim>> bed_normal;
    const bool fills_bed = bed && mat_.traits().fluid && !mat_.traits().rigid;
    while (true) {
      column.clear();
      bed_column.clear();
      bed_normal.clear();
      for (k[up] = lo_[up]; k[up] <= hi_[up]; ++k[up]) {
        DVec<dim> x;
        for (int a = 0; a < dim; ++a) x[a] = (k[a] + 0.5) * h_;
        x[up] += shift_;
        Vec<dim> n = Vec<dim>::Zero();  // set by filled() for the bed layer
        const Fill f = filled(x, n);
        if (f == Fill::Material) column.push_back(x);
        if (f == Fill::BedLayer && fills_bed) {
          bed_column.push_back(x);
          bed_normal.push_back(n);
        }
      }
      std::optional<double> level;
      if (crevasse_water_) level = keep_crevasse_water(column);
      else if (body_.crevasses) cut_crevasse(column);
      seed_column(column, particles, &seeding_, level);
      if (!bed_column.empty()) {
        seed_column(bed_column, bed->particles, nullptr);
        bed->normal.insert(bed->normal.end(), bed_normal.begin(), bed_normal.end());
      }
      int a = up - 1;
      for (; a >= 0; --a) {
        if (++k[a] <= hi_[a]) break;
        k[a] = lo_[a];
      }
      if (a < 0) break;
    }
  }

 private:
  enum class Fill { None, Material, BedLayer };
  // Whether lattice point x holds a particle of the body, one of a bed layer (with the bed's normal n: inside
  // the body's shape, in the bed layer of one boundary and the solid of no other), or nothing.
  Fill filled(const DVec<dim>& x, Vec<dim>& n) const {
    if (!body_.shape.contains(x)) return Fill::None;
    if (body_.track && !body_.track->occupied(x[0], x[vertical_axis<dim>])) return Fill::None;
    if (body_.solitary && x[vertical_axis<dim>] >= body_.solitary->surface(x[0])) return Fill::None;
    for (const auto& h : body_.holes)
      if (h.contains(x)) return Fill::None;
    for (const Tilted<dim>& t : rigid_shapes_)
      if (t.contains(x)) return Fill::None;
    const Vec<dim> xr = x.template cast<Real>();
    int solid = 0, layer = 0;
    for (const auto& b : boundaries_) {
      if (!b->is_solid(xr)) continue;
      ++solid;
      Vec<dim> nb;
      if (b->in_bed_layer(xr, nb)) ++layer, n = nb;
    }
    if (solid == 0) return Fill::Material;
    return solid == 1 && layer == 1 ? Fill::BedLayer : Fill::None;
  }

  // The crevasse cutting a column (shape/crevasse_field.h): its depth d (0 if none) and its bottom, d below the
  // column's top ice (or the field's given surface).
  struct Cut {
    double depth = 0, bottom = 0;
  };
  Cut crevasse_cut(const std::vector<DVec<dim>>& column) const {
    constexpr int up = vertical_axis<dim>;
    if (column.empty()) return {};
    const CrevasseField& field = *body_.crevasses;
    const double d = field.cut_depth(column.front()[0], dim == 3 ? column.front()[1] : 0.0);
    if (d <= 0) return {};
    return {d, (field.surface ? *field.surface : column.back()[up] + 0.5 * h_) - d};
  }

  // Removes the lattice points of a column in a surface crevasse: those above the crevasse's bottom.
  void cut_crevasse(std::vector<DVec<dim>>& column) const {
    const Cut c = crevasse_cut(column);
    if (c.depth > 0) std::erase_if(column, [&](const DVec<dim>& x) { return x[vertical_axis<dim>] > c.bottom; });
  }

  // Keeps the lattice points of a column that its crevasse cuts and the crevasse's water fills: above the bottom
  // and at most water_depth above it. Returns the water's level (its free surface) in this column.
  double keep_crevasse_water(std::vector<DVec<dim>>& column) const {
    const Cut c = crevasse_cut(column);
    const double level = c.bottom + std::min(body_.crevasses->water_depth, c.depth);
    std::erase_if(column, [&](const DVec<dim>& x) {
      return c.depth <= 0 || x[vertical_axis<dim>] <= c.bottom || x[vertical_axis<dim>] > level;
    });
    return level;
  }

  // The pressure of a fluid column at rest at the depth d of each of its points below `level` (0 above it). Its
  // particles carry the compressed density rho0 / J(p) (the mass rho0 V0 in the volume V0 J), so the weight above
  // depth d is the integral of rho0 g / J(p):
  //   dp/dd = rho0 g / J(p),  p(0) = 0,
  // integrated with classical Runge-Kutta down the column, point after point in order of depth, in steps of at most
  // the lattice spacing (J(p) of the material's initial_state; for the Tait water
  // p = K/gamma [(1 + (gamma - 1) rho0 g d / K)^(gamma/(gamma-1)) - 1]). p = rho0 g d instead leaves every column
  // lighter than the pressure under it by about rho0 g d / (2K), and the water then rings at its vertical acoustic
  // period (docs/changelog.md, "What the water does around the rising blob").
  std::vector<double> column_pressures(const std::vector<DVec<dim>>& column, double level, double rho0_g) const {
    constexpr int up = vertical_axis<dim>;
    const auto slope = [&](double p) {
      const Real J = mat_.visit([&](const auto& model) {
        return model.template initial_state<dim>(static_cast<Real>(p), Real(0)).J;
      });
      return rho0_g / static_cast<double>(J);
    };
    std::vector<size_t> order(column.size());
    std::iota(order.begin(), order.end(), size_t(0));
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return column[a][up] > column[b][up]; });
    std::vector<double> pressure(column.size(), 0.0);
    double d = 0, p = 0;
    for (const size_t k : order) {
      const double target = level - column[k][up];
      if (target > d) {
        const int steps = std::max(1, static_cast<int>(std::ceil((target - d) / h_ - 1e-9)));
        const double h = (target - d) / steps;
        for (int i = 0; i < steps; ++i) {
          const double k1 = slope(p), k2 = slope(p + 0.5 * h * k1), k3 = slope(p + 0.5 * h * k2), k4 = slope(p + h * k3);
          p += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
        }
        d = target;
      }
      pressure[k] = p;
    }
    return pressure;
  }

  // Solids: depth below the body's own top surface in this column (a sloping slab); others: below the level
  // (`level_override`, when given, for the water in a crevasse). With `seeding`, each particle gets the next index
  // of the one-process array as its id, and only those seeding.keep accepts are added (the bed layer's: all).
  void seed_column(const std::vector<DVec<dim>>& column, Particles<dim>& particles, Seeding<dim>* seeding,
                   std::optional<double> level_override = std::nullopt) const {
    constexpr int up = vertical_axis<dim>;
    const double g = -static_cast<Real>(scene_.gravity[up]);
    const bool loaded = body_.hydrostatic && g > 0;
    const bool solid = mat_.traits().solid_state;
    const double top = column.empty() ? 0 : column.back()[up] + 0.5 * h_;
    const double surface = body_.surface_level ? *body_.surface_level : body_.shape.upper(up);
    double level = solid && !body_.surface_level ? top : surface;
    if (body_.solitary && !column.empty()) level = body_.solitary->surface(column.front()[0]);
    if (level_override) level = *level_override;
    const Real rho0 = mat_.density();
    std::vector<double> fluid_pressure;  // fluids: down the column from its level (column_pressures)
    if (!solid && loaded) fluid_pressure = column_pressures(column, level, rho0 * g);
    for (size_t i = 0; i < column.size(); ++i) {
      const DVec<dim>& x = column[i];
      Vec<dim> xp = x.template cast<Real>();
      if (mat_.traits().rigid) xp = self_.pivot + self_.R * (xp - self_.pivot);
      const uint64_t index = seeding ? seeding->seeded++ : 0;
      if (seeding && !seeding->touched)
        for (const OffGridFace& f : seeding->off_grid)
          if (x[f.axis] > f.position - scene_.domain.dx) {
            seeding->touched = &f;
            seeding->toucher = "bodies[" + std::to_string(&body_ - scene_.bodies.data()) + "]" +
                               (crevasse_water_ ? ".crevasses" : "");
          }
      if (seeding && seeding->keep && !seeding->keep(index, xp)) continue;
      const Real pressure =
          static_cast<Real>(solid ? rho0 * g * std::max(0.0, level - x[up]) : (loaded ? fluid_pressure[i] : 0.0));
      const InitialState<dim> st =
          mat_.visit([&](const auto& model) { return model.template initial_state<dim>(loaded ? pressure : Real(0), static_cast<Real>(body_.lateral_stress_ratio)); });
      // The particle occupies volume h^dim now; its reference (unstressed) volume is that over J. A shifted
      // liquid's lowest particle in a column that stands on the shape's bottom (its cell's lower edge within half
      // a spacing of it) takes the volume from the bottom to its cell's upper edge, so each column holds the
      // water between the shape's bottom and the level.
      double share = 1;
      if (shift_ != 0 && i == 0) {
        const double gap = x[up] - 0.5 * h_ - body_.shape.lower(up);
        if (std::abs(gap) <= 0.5 * h_) share = 1 - gap / h_;
      }
      const Real V0 = cell_volume_ * static_cast<Real>(share) / st.J;
      // A rigid body's density is its mass over the volume it fills: rho_b h^dim per particle. Its J (the Tait state
      // of the column pressure down from its level, for the penalty pressure that keeps the water out of it,
      // material/rigid.h) does not make it heavier: with rho_b V0 = rho_b h^dim / J a block under 1 m of the scenes' water (K = 1e6 Pa) weighs 1 %
      // more than rho_b V, a tenth of the net buoyancy of a block of density 920 (docs/validation.md).
      const Real mass = mat_.traits().rigid ? rho0 * cell_volume_ * static_cast<Real>(share) : rho0 * V0;
      // v(x) = velocity + G (x - c), c the centre of the shape's bounding box.
      Vec<dim> vp = v0_ + G_ * (xp - centre_);
      if (body_.solitary) {  // sim/solitary_wave.h
        vp[0] += static_cast<Real>(body_.solitary->u(x[0], g));
        vp[up] += static_cast<Real>(body_.solitary->w(x[0], x[up], g));
      }
      const MaterialId id = static_cast<MaterialId>(material_index_);
      if (solid) particles.add_solid(xp, vp, mass, st.J, id, G_, st.F, st.alpha, st.Fz);
      else particles.add_fluid(xp, vp, mass, st.J, id, G_);
      if (seeding) particles.id[solid ? particles.solid_count() - 1 : particles.size() - 1] = index;
    }
  }

  const Scene& scene_;
  const BodySpec& body_;
  bool crevasse_water_;
  int material_index_;
  const Material& mat_;
  const std::vector<std::unique_ptr<Boundary<dim>>>& boundaries_;
  Seeding<dim>& seeding_;
  Tilted<dim> self_;
  std::vector<Tilted<dim>> rigid_shapes_;
  int n_ = 1;
  double h_ = 1;
  double shift_ = 0;  // the vertical offset of a liquid's lattice from the grid's (0 or in (-h, 0))
  IVec<dim> lo_, hi_;
  Vec<dim> v0_, centre_;  // the body's initial velocity and the centre of its bounding box
  Mat<dim> G_;            // its initial velocity gradient (also the particles' APIC matrix)
  Real cell_volume_ = 1;  // h^dim, a particle's current volume
};

}  // namespace

template <int dim>
uint64_t seed_bodies(const Scene& scene, std::vector<Material>& materials,
                 const std::vector<std::unique_ptr<Boundary<dim>>>& boundaries, Particles<dim>& particles,
                 BedLayer<dim>* bed, const SeedFilter<dim>& keep) {
  Seeding<dim> seeding{keep, 0, off_grid_wall_faces(scene, boundaries)};
  for (const bool solids : {true, false})
    for (size_t i = 0; i < scene.bodies.size(); ++i) {
      const BodySpec& b = scene.bodies[i];
      Material& mat = materials[b.material_index];
      if (mat.traits().solid_state != solids) continue;
      const BodySeeder<dim> seeder(scene, b, materials, boundaries, seeding);
      mat.half_spacing = std::max(mat.half_spacing, static_cast<Real>(0.5 * seeder.spacing()));
      const uint64_t before = seeding.seeded;
      seeder.seed(particles, bed);
      if (seeding.seeded == before)
        throw SceneError(scene.path + ": bodies[" + std::to_string(i) + "]: seeds no particle (its shape is smaller "
                         "than the particle spacing, or lies inside its holes, a rigid body or the solid of a boundary)");
    }
  // The water in the crevasses of ice bodies, after every other fluid (fluids follow solids in memory).
  for (size_t i = 0; i < scene.bodies.size(); ++i) {
    const BodySpec& b = scene.bodies[i];
    if (!b.crevasses || b.crevasses->water_depth <= 0) continue;
    Material& water = materials[b.crevasses->water_material_index];
    const BodySeeder<dim> seeder(scene, b, materials, boundaries, seeding, true);
    water.half_spacing = std::max(water.half_spacing, static_cast<Real>(0.5 * seeder.spacing()));
    seeder.seed(particles, nullptr);
  }
  if (const OffGridFace* f = seeding.touched) {
    const std::string size = "domain.size[" + std::to_string(f->axis) + "]", dx = format_number(scene.domain.dx);
    throw SceneError(scene.path + ": " + f->where + ": the wall face \"" + f->name + "\" lies at " + size + " = " +
                     format_number(f->position) + " m, " + format_number(f->cells) + " cells of dx = " + dx + " m, and " +
                     seeding.toucher + " is seeded within a cell of it; a wall acts on grid nodes, so a face that " +
                     "material touches must lie on a grid plane: make " + size + " a whole number of cells (" +
                     format_number(std::floor(f->cells) * scene.domain.dx) + " or " +
                     format_number(std::ceil(f->cells) * scene.domain.dx) + " m)");
  }
  particles.next_id = seeding.seeded;
  return seeding.seeded;
}

template uint64_t seed_bodies<2>(const Scene&, std::vector<Material>&, const std::vector<std::unique_ptr<Boundary<2>>>&,
                                  Particles<2>&, BedLayer<2>*, const SeedFilter<2>&);
template uint64_t seed_bodies<3>(const Scene&, std::vector<Material>&, const std::vector<std::unique_ptr<Boundary<3>>>&,
                                  Particles<3>&, BedLayer<3>*, const SeedFilter<3>&);

}  // namespace cdmpm
