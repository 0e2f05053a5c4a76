// test_icebergs.cpp - iceberg detection (probe/icebergs.h): connected bodies of intact ice on the grid.
//
// Particles sit at cell centres or quarter points of cells with dx = 1/4 and spacing h = dx/2, volumes
// h^dim: every position, volume, sum and quotient checked below is a short dyadic fraction, exact in float
// and double, so the expected values are exact.
#include <gtest/gtest.h>

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <random>

#include "probe/icebergs.h"

namespace cdmpm {
namespace {

constexpr Real dx = Real(0.25), h = Real(0.125);  // two particles per cell per axis

template <int dim>
struct Cloud {
  std::vector<Vec<dim>> x;
  std::vector<Real> volume, damage;
  std::vector<uint8_t> ice;

  // Particles filling cells [c0, c1) (cell coordinates, both ends per axis), 2 per cell per axis.
  void box(const IVec<dim>& c0, const IVec<dim>& c1, Real dmg = 0, bool is_ice = true) {
    IVec<dim> lo = 2 * c0, hi = 2 * c1, i = lo;
    while (true) {
      Vec<dim> p;
      for (int a = 0; a < dim; ++a) p[a] = (Real(i[a]) + Real(0.5)) * h;
      add(p, dmg, is_ice);
      int a = dim - 1;
      while (a >= 0 && ++i[a] == hi[a]) {
        i[a] = lo[a];
        --a;
      }
      if (a < 0) break;
    }
  }
  void add(const Vec<dim>& p, Real dmg = 0, bool is_ice = true) {
    x.push_back(p);
    volume.push_back(std::pow(h, Real(dim)));
    damage.push_back(dmg);
    ice.push_back(is_ice ? 1 : 0);
  }
  std::vector<IceBody<dim>> bodies(size_t min_particles = 1, std::vector<int>* label = nullptr) const {
    return find_ice_bodies<dim>(x, volume, damage, ice, dx, h, 0, Real(0.5), min_particles, label);
  }
};

IVec<2> c2(int i, int j) { return IVec<2>(i, j); }
IVec<3> c3(int i, int j, int k) { return IVec<3>(i, j, k); }

// Every labelled particle is counted in its body, and each body's count matches its labels.
template <int dim>
void expect_labels_consistent(const Cloud<dim>& c, const std::vector<IceBody<dim>>& b, const std::vector<int>& label) {
  ASSERT_EQ(label.size(), c.x.size());
  std::vector<size_t> count(b.size(), 0);
  for (size_t p = 0; p < label.size(); ++p) {
    ASSERT_GE(label[p], -1);
    ASSERT_LT(label[p], int(b.size()));
    if (label[p] < 0) continue;
    EXPECT_TRUE(c.ice[p]);
    EXPECT_LT(c.damage[p], 0.5);
    ++count[label[p]];
  }
  for (size_t k = 0; k < b.size(); ++k) {
    EXPECT_EQ(b[k].id, int(k));
    EXPECT_EQ(b[k].particles, count[k]);
  }
}

TEST(IceBodies, SolidRectangleIsOneBody) {
  Cloud<2> c;
  c.box(c2(0, 0), c2(10, 4));  // 20 x 8 particles: 2.5 x 1.0
  std::vector<int> label;
  const auto b = c.bodies(1, &label);
  ASSERT_EQ(b.size(), 1u);
  EXPECT_EQ(b[0].id, 0);
  EXPECT_EQ(b[0].particles, 160u);
  EXPECT_EQ(b[0].volume, Real(2.5));
  EXPECT_EQ(b[0].length, Real(2.5));
  EXPECT_EQ(b[0].height, Real(1.0));
  EXPECT_EQ(b[0].centroid, Vec<2>(1.25, 0.5));
  EXPECT_EQ(b[0].lo, Vec<2>(h / 2, h / 2));
  EXPECT_EQ(b[0].hi, Vec<2>(2.5 - h / 2, 1.0 - h / 2));
  expect_labels_consistent(c, b, label);
  for (int l : label) EXPECT_EQ(l, 0);
}

TEST(IceBodies, DamagedColumnSplitsRectangle) {
  Cloud<2> c;
  c.box(c2(0, 0), c2(6, 4));
  c.box(c2(6, 0), c2(7, 4), 1);  // fully damaged column of cells
  c.box(c2(7, 0), c2(10, 4));
  std::vector<int> label;
  const auto b = c.bodies(1, &label);
  ASSERT_EQ(b.size(), 2u);
  EXPECT_EQ(b[0].length, Real(1.5));  // cells 0..5, the larger: the glacier
  EXPECT_EQ(b[0].volume, Real(1.5));
  EXPECT_EQ(b[0].centroid[0], Real(0.75));
  EXPECT_EQ(b[1].length, Real(0.75));  // cells 7..9
  EXPECT_EQ(b[1].volume, Real(0.75));
  EXPECT_EQ(b[1].centroid[0], Real(2.125));
  EXPECT_EQ(b[0].particles + b[1].particles, 160u - 16u);
  expect_labels_consistent(c, b, label);
  for (size_t p = 0; p < c.x.size(); ++p) {
    if (c.damage[p] > 0) {
      EXPECT_EQ(label[p], -1);
    }
  }
}

TEST(IceBodies, DamageBelowThresholdDoesNotSplit) {
  Cloud<2> c;
  c.box(c2(0, 0), c2(6, 4));
  c.box(c2(6, 0), c2(7, 4), Real(0.3));
  c.box(c2(7, 0), c2(10, 4));
  const auto b = c.bodies();
  ASSERT_EQ(b.size(), 1u);
  EXPECT_EQ(b[0].particles, 160u);
  EXPECT_EQ(b[0].length, Real(2.5));
}

TEST(IceBodies, CellMeanDamageDecidesIntactness) {
  // One cell of the bridge column holds 3 damaged particles and 1 intact one (mean 0.75): the column
  // is broken there only if every cell of it is; here the other three cells are intact, so one body,
  // and the damaged particles belong to none.
  Cloud<2> c;
  c.box(c2(0, 0), c2(3, 4));
  c.box(c2(3, 1), c2(4, 4));
  c.add(Vec<2>(3 * dx + h / 2, h / 2), 1);
  c.add(Vec<2>(3 * dx + h / 2, 3 * h / 2), 1);
  c.add(Vec<2>(3 * dx + 3 * h / 2, h / 2), 1);
  const size_t lone = c.x.size();
  c.add(Vec<2>(3 * dx + 3 * h / 2, 3 * h / 2), 0);  // intact particle in a damaged cell: belongs to none
  c.box(c2(4, 0), c2(6, 4));
  std::vector<int> label;
  const auto b = c.bodies(1, &label);
  ASSERT_EQ(b.size(), 1u);
  EXPECT_EQ(b[0].particles, 96u - 4u);
  EXPECT_EQ(label[lone], -1);
  expect_labels_consistent(c, b, label);

  // Damaging the rest of the column splits it.
  Cloud<2> d = c;
  for (size_t p = 0; p < d.x.size(); ++p)
    if (ice_cell_coord(d.x[p][0], dx) == 3) d.damage[p] = 1;
  EXPECT_EQ(d.bodies().size(), 2u);
}

TEST(IceBodies, EmptyGapOfOneCellSeparates) {
  Cloud<2> c;
  c.box(c2(0, 0), c2(4, 4));
  c.box(c2(5, 0), c2(8, 4));  // cell column 4 is empty
  const auto b = c.bodies();
  ASSERT_EQ(b.size(), 2u);
  EXPECT_EQ(b[0].length, Real(1.0));
  EXPECT_EQ(b[1].length, Real(0.75));
}

TEST(IceBodies, WaterNeitherConnectsNorCounts) {
  Cloud<2> c;
  c.box(c2(-2, -2), c2(12, 0), 0, false);  // water below, at negative coordinates
  c.box(c2(0, 0), c2(4, 4));
  c.box(c2(4, 0), c2(5, 6), 0, false);     // water filling the gap and above it
  c.box(c2(5, 0), c2(8, 4));
  c.box(c2(8, 0), c2(12, 2), 1, false);    // damaged water: irrelevant
  std::vector<int> label;
  const auto b = c.bodies(1, &label);
  ASSERT_EQ(b.size(), 2u);
  EXPECT_EQ(b[0].particles, 64u);
  EXPECT_EQ(b[0].volume, Real(1.0));
  EXPECT_EQ(b[1].particles, 48u);
  EXPECT_EQ(b[1].volume, Real(0.75));
  expect_labels_consistent(c, b, label);
  for (size_t p = 0; p < c.x.size(); ++p) {
    if (!c.ice[p]) {
      EXPECT_EQ(label[p], -1);
    }
  }
}

TEST(IceBodies, DiagonalContactDoesNotConnect2D) {
  Cloud<2> c;
  c.box(c2(0, 0), c2(2, 2));
  c.box(c2(2, 2), c2(4, 4));  // shares only the corner (2, 2) with the first
  EXPECT_EQ(c.bodies().size(), 2u);
  c.box(c2(2, 1), c2(3, 2));  // a face-sharing cell joins them
  EXPECT_EQ(c.bodies().size(), 1u);
}

TEST(IceBodies, DiagonalContactDoesNotConnect3D) {
  Cloud<3> c;
  c.box(c3(0, 0, 0), c3(1, 1, 1));
  c.box(c3(1, 1, 0), c3(2, 2, 1));  // edge contact
  c.box(c3(2, 2, 1), c3(3, 3, 2));  // corner contact
  EXPECT_EQ(c.bodies().size(), 3u);
}

TEST(IceBodies, DebrisBelowMinParticlesDropped) {
  Cloud<2> c;
  c.box(c2(0, 0), c2(4, 4));   // 64 particles
  c.box(c2(6, 0), c2(7, 1));   // 4 particles: debris
  c.box(c2(9, 0), c2(11, 1));  // 8 particles
  std::vector<int> label;
  auto b = c.bodies(5, &label);
  ASSERT_EQ(b.size(), 2u);
  EXPECT_EQ(b[0].particles, 64u);
  EXPECT_EQ(b[1].particles, 8u);
  expect_labels_consistent(c, b, label);
  for (size_t p = 64; p < 68; ++p) EXPECT_EQ(label[p], -1);
  EXPECT_EQ(c.bodies(4).size(), 3u);
  EXPECT_EQ(c.bodies(9).size(), 1u);
  EXPECT_EQ(c.bodies(65).size(), 0u);
}

TEST(IceBodies, OrderedByVolumeThenFlowPosition) {
  Cloud<2> c;
  c.box(c2(20, 0), c2(22, 2));  // 4 cells, furthest downstream
  c.box(c2(0, 0), c2(1, 1));    // 1 cell
  c.box(c2(10, 0), c2(16, 2));  // 12 cells: the glacier although listed third
  c.box(c2(3, 0), c2(5, 2));    // 4 cells, upstream of the other 4-cell body: comes first
  std::vector<int> label;
  const auto b = c.bodies(1, &label);
  ASSERT_EQ(b.size(), 4u);
  EXPECT_EQ(b[0].volume, Real(0.75));
  EXPECT_EQ(b[1].volume, Real(0.25));
  EXPECT_EQ(b[1].centroid[0], Real(1.0));
  EXPECT_EQ(b[2].volume, Real(0.25));
  EXPECT_EQ(b[2].centroid[0], Real(5.25));
  EXPECT_EQ(b[3].volume, Real(0.0625));
  expect_labels_consistent(c, b, label);
  EXPECT_EQ(label[0], 2);    // first particle of the downstream 4-cell body
  EXPECT_EQ(label[16], 3);   // the 1-cell body
  EXPECT_EQ(label[20], 0);   // the glacier
  EXPECT_EQ(label.back(), 1);
}

TEST(IceBodies, NoIceGivesNoBodies) {
  Cloud<2> c;
  EXPECT_TRUE(c.bodies().empty());
  c.box(c2(0, 0), c2(2, 2), 0, false);
  std::vector<int> label;
  EXPECT_TRUE(c.bodies(1, &label).empty());
  EXPECT_EQ(label, std::vector<int>(16, -1));
}

TEST(IceBodies, PositionOnCellFaceGoesToTheCellAbove) {
  // dx = 1/4 is exact: x = 2 dx lies on the face between cells 1 and 2 and goes to cell 2 (floor).
  EXPECT_EQ(ice_cell_coord(2 * dx, dx), 2);
  EXPECT_EQ(ice_cell_coord(std::nextafter(2 * dx, Real(0)), dx), 1);
  EXPECT_EQ(ice_cell_coord(-dx, dx), -1);
  EXPECT_EQ(ice_cell_coord(Real(-0.0), dx), 0);
  Cloud<2> c;
  c.box(c2(0, 0), c2(1, 1));    // cell 0
  c.add(Vec<2>(2 * dx, h / 2));  // on the face of cells 1|2: cell 2, no contact with cell 0
  c.box(c2(3, 0), c2(4, 1));    // cell 3: touches cell 2
  std::vector<int> label;
  auto b = c.bodies(1, &label);
  ASSERT_EQ(b.size(), 2u);
  EXPECT_EQ(label[4], label[5]);
  EXPECT_NE(label[4], label[0]);
  EXPECT_EQ(b[label[4]].particles, 5u);
  // Nudged just below the face it falls in cell 1 and joins cell 0 instead.
  c.x[4][0] = std::nextafter(2 * dx, Real(0));
  b = c.bodies(1, &label);
  ASSERT_EQ(b.size(), 2u);
  EXPECT_EQ(label[4], label[0]);
  EXPECT_NE(label[4], label[5]);
  // A non-dyadic cell size: same position, same cell, every call, whatever side rounding picks.
  const Real dx3 = Real(0.1), xf = 3 * dx3;
  const int64_t cell = ice_cell_coord(xf, dx3);
  EXPECT_TRUE(cell == 2 || cell == 3);
  for (int k = 0; k < 10; ++k) EXPECT_EQ(ice_cell_coord(xf, dx3), cell);
}

TEST(IceBodies, NegativePositionsSplitByDamage) {
  Cloud<2> c;
  c.box(c2(-6, -3), c2(-2, 1));
  c.box(c2(-2, -3), c2(-1, 1), 1);
  c.box(c2(-1, -3), c2(1, 1));
  const auto b = c.bodies();
  ASSERT_EQ(b.size(), 2u);
  EXPECT_EQ(b[0].length, Real(1.0));
  EXPECT_EQ(b[0].lo, Vec<2>(-1.5 + h / 2, -0.75 + h / 2));
  EXPECT_EQ(b[1].length, Real(0.5));
  EXPECT_EQ(b[1].height, Real(1.0));
}

TEST(IceBodies, RejectsBadInput) {
  Cloud<2> c;
  c.box(c2(0, 0), c2(1, 1));
  EXPECT_THROW(find_ice_bodies<2>(c.x, c.volume, c.damage, c.ice, 0, h, 0, Real(0.5), 1), std::invalid_argument);
  EXPECT_THROW(find_ice_bodies<2>(c.x, c.volume, c.damage, c.ice, dx, h, 2, Real(0.5), 1), std::invalid_argument);
  c.volume.pop_back();
  EXPECT_THROW(find_ice_bodies<2>(c.x, c.volume, c.damage, c.ice, dx, h, 0, Real(0.5), 1), std::invalid_argument);
  c.volume.push_back(h * h);
  c.x[0][1] = std::numeric_limits<Real>::quiet_NaN();
  EXPECT_THROW(find_ice_bodies<2>(c.x, c.volume, c.damage, c.ice, dx, h, 0, Real(0.5), 1), std::invalid_argument);
}

TEST(IceBodies3D, DamagedSlabSplitsBox) {
  Cloud<3> c;
  c.box(c3(0, 0, 0), c3(5, 2, 3));
  c.box(c3(5, 0, 0), c3(6, 2, 3), 1);  // damaged slab across the whole section
  c.box(c3(6, 0, 0), c3(8, 2, 3));
  std::vector<int> label;
  const auto b = c.bodies(1, &label);
  ASSERT_EQ(b.size(), 2u);
  const Real cell_volume = dx * dx * dx;
  EXPECT_EQ(b[0].volume, 30 * cell_volume);
  EXPECT_EQ(b[0].particles, 240u);
  EXPECT_EQ(b[0].length, Real(1.25));
  EXPECT_EQ(b[0].height, Real(0.75));
  EXPECT_EQ(b[0].centroid, Vec<3>(0.625, 0.25, 0.375));
  EXPECT_EQ(b[1].volume, 12 * cell_volume);
  EXPECT_EQ(b[1].particles, 96u);
  EXPECT_EQ(b[1].length, Real(0.5));
  EXPECT_EQ(b[1].centroid[0], Real(1.75));
  expect_labels_consistent(c, b, label);
}

TEST(IceBodies3D, LShapedBodyIsOne) {
  Cloud<3> c;
  c.box(c3(0, 0, 0), c3(6, 2, 2));  // horizontal bar
  c.box(c3(0, 0, 2), c3(2, 2, 6));  // vertical bar on its end
  const auto b = c.bodies();
  ASSERT_EQ(b.size(), 1u);
  EXPECT_EQ(b[0].particles, 8u * (24 + 16));
  EXPECT_EQ(b[0].volume, 40 * dx * dx * dx);
  EXPECT_EQ(b[0].length, Real(1.5));
  EXPECT_EQ(b[0].height, Real(1.5));
}

TEST(IceBodies3D, SameResultWithOneOrTwoThreads) {
  // Random damage over a box: many bodies of many sizes; results must match bit for bit.
  Cloud<3> c;
  c.box(c3(-8, 0, -4), c3(24, 16, 12));
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> coin(0, 9);
  std::vector<Real> cell_damage(32 * 16 * 16);  // 70% of the cells damaged: below percolation
  for (Real& d : cell_damage) d = Real(coin(rng) < 7);
  for (size_t p = 0; p < c.x.size(); ++p) {
    const int64_t i = ice_cell_coord(c.x[p][0], dx) + 8, j = ice_cell_coord(c.x[p][1], dx),
                  k = ice_cell_coord(c.x[p][2], dx) + 4;
    c.damage[p] = cell_damage[(i * 16 + j) * 16 + k];
  }
  const int threads = omp_get_max_threads();
  std::vector<int> l1, l2;
  omp_set_num_threads(1);
  const auto b1 = c.bodies(2, &l1);
  omp_set_num_threads(2);
  const auto b2 = c.bodies(2, &l2);
  omp_set_num_threads(threads);
  ASSERT_GT(b1.size(), 10u);
  ASSERT_EQ(b1.size(), b2.size());
  EXPECT_EQ(l1, l2);
  for (size_t k = 0; k < b1.size(); ++k) {
    EXPECT_EQ(b1[k].particles, b2[k].particles);
    EXPECT_EQ(b1[k].volume, b2[k].volume);
    EXPECT_EQ(b1[k].centroid, b2[k].centroid);
    EXPECT_EQ(b1[k].lo, b2[k].lo);
    EXPECT_EQ(b1[k].hi, b2[k].hi);
  }
  expect_labels_consistent(c, b1, l1);
}

// The detection split into parts as a distributed run splits it (parallel/rank_icebergs.h): each part holds the ice
// of the cells it is home to, in a scrambled order with the one-process index as order key, and finds its
// components and rim; merge_ice_parts joins them. The bodies and labels must be those of one process, bit for bit.
template <int dim, class Home>
std::vector<IceBody<dim>> split_bodies(const Cloud<dim>& c, int parts, const Home& home, size_t min_particles,
                                       std::vector<int>& label) {
  using Cell = typename IcePart<dim>::Cell;
  std::vector<std::vector<size_t>> members(static_cast<size_t>(parts));
  for (size_t p = 0; p < c.x.size(); ++p) {
    if (!c.ice[p]) continue;
    Cell cell;
    for (int a = 0; a < dim; ++a) cell[a] = ice_cell_coord(c.x[p][a], dx);
    members[static_cast<size_t>(home(cell))].push_back(p);
  }
  std::vector<IcePart<dim>> split;
  for (int r = 0; r < parts; ++r) {
    std::vector<size_t>& m = members[static_cast<size_t>(r)];
    std::mt19937 rng(static_cast<unsigned>(r + 5));
    std::shuffle(m.begin(), m.end(), rng);
    std::vector<Vec<dim>> x;
    std::vector<Real> volume, damage;
    std::vector<uint64_t> key;
    for (size_t p : m) x.push_back(c.x[p]), volume.push_back(c.volume[p]), damage.push_back(c.damage[p]), key.push_back(p);
    const std::vector<uint8_t> ice(m.size(), 1);
    IceBodyFinder<dim> finder(x, volume, damage, ice, &key, dx, Real(0.5));
    if (!finder.bin_cells()) {
      split.emplace_back().component.assign(m.size(), -1);
      continue;
    }
    finder.occupy();
    finder.unite();
    const auto elsewhere = [&](const Cell& cell) { return home(cell) != r; };
    split.push_back(finder.part(min_particles, &elsewhere));
  }
  std::vector<std::vector<int>> body_of;
  auto bodies = merge_ice_parts<dim>(split, h, 0, min_particles, body_of);
  label.assign(c.x.size(), -1);
  for (int r = 0; r < parts; ++r)
    for (size_t i = 0; i < members[static_cast<size_t>(r)].size(); ++i) {
      const int32_t k = split[static_cast<size_t>(r)].component[i];
      label[members[static_cast<size_t>(r)][i]] = k < 0 ? -1 : body_of[static_cast<size_t>(r)][static_cast<size_t>(k)];
    }
  return bodies;
}

template <int dim>
void expect_same_bodies(const std::vector<IceBody<dim>>& a, const std::vector<IceBody<dim>>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k].particles, b[k].particles) << "body " << k;
    EXPECT_EQ(a[k].volume, b[k].volume) << "body " << k;
    EXPECT_EQ(a[k].centroid, b[k].centroid) << "body " << k;
    EXPECT_EQ(a[k].lo, b[k].lo) << "body " << k;
    EXPECT_EQ(a[k].hi, b[k].hi) << "body " << k;
    EXPECT_EQ(a[k].length, b[k].length) << "body " << k;
  }
}

// Random damage and random (non-dyadic) volumes over a box: a fraction `intact` of the cells intact (below the
// site-percolation threshold: many bodies, most of them crossing the parts' cuts), some particles of intact cells
// damaged, water among the ice.
template <int dim>
Cloud<dim> random_cloud(const IVec<dim>& c0, const IVec<dim>& c1, double intact, unsigned seed) {
  Cloud<dim> c;
  c.box(c0, c1);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::map<std::array<int64_t, dim>, bool> cell_intact;
  for (size_t p = 0; p < c.x.size(); ++p) {
    std::array<int64_t, dim> k;
    for (int a = 0; a < dim; ++a) k[a] = ice_cell_coord(c.x[p][a], dx);
    const auto [it, fresh] = cell_intact.try_emplace(k, false);
    if (fresh) it->second = u(rng) < intact;
    c.volume[p] *= Real(0.5 + u(rng));
    c.damage[p] = Real(it->second ? (u(rng) < 0.1 ? 0.6 + 0.4 * u(rng) : 0.3 * u(rng)) : 0.4 + 0.6 * u(rng));
  }
  for (size_t p = 0; p < c.x.size(); p += 7) c.ice[p] = 0;
  return c;
}

TEST(IceBodies, PartsJoinedAcrossCutsGiveTheOneProcessBodies) {
  const Cloud<2> c = random_cloud<2>(c2(-6, 0), c2(30, 20), 0.55, 3);
  std::vector<int> l1, l3, l4;
  const auto one = c.bodies(3, &l1);
  ASSERT_GT(one.size(), 5u);
  // Three parts cut along x, and four in a checkerboard of 5-cell squares (cuts along both axes).
  const auto b3 = split_bodies<2>(c, 3, [](const IcePart<2>::Cell& k) { return k[0] < 4 ? 0 : k[0] < 13 ? 1 : 2; }, 3, l3);
  const auto b4 = split_bodies<2>(
      c, 4, [](const IcePart<2>::Cell& k) { return int(((k[0] + 100) / 5) % 2 + 2 * (((k[1] + 100) / 5) % 2)); }, 3, l4);
  expect_same_bodies<2>(one, b3);
  expect_same_bodies<2>(one, b4);
  EXPECT_EQ(l1, l3);
  EXPECT_EQ(l1, l4);
  expect_labels_consistent(c, one, l1);
}

TEST(IceBodies3D, PartsJoinedAcrossCutsGiveTheOneProcessBodies) {
  const Cloud<3> c = random_cloud<3>(c3(-4, 0, -2), c3(12, 10, 8), 0.3, 8);
  std::vector<int> l1, l5;
  const auto one = c.bodies(2, &l1);
  ASSERT_GT(one.size(), 5u);
  const auto b5 = split_bodies<3>(
      c, 5, [](const IcePart<3>::Cell& k) { return int(((k[0] + 64) / 3 + (k[1] + 64) / 4 + (k[2] + 64) / 2) % 5); }, 2,
      l5);
  expect_same_bodies<3>(one, b5);
  EXPECT_EQ(l1, l5);
}

TEST(IceBodies3D, TwoMillionParticlesOneBody) {
  // 64 x 64 x 64 cells, 8 particles each: 2,097,152 particles (a size the probe must handle quickly).
  Cloud<3> c;
  c.box(c3(0, 0, 0), c3(64, 64, 64));
  std::vector<int> label;
  const auto t0 = std::chrono::steady_clock::now();
  const auto b = c.bodies(1, &label);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  RecordProperty("seconds", std::to_string(seconds));
  ASSERT_EQ(b.size(), 1u);
  EXPECT_EQ(b[0].particles, c.x.size());
  EXPECT_EQ(b[0].length, Real(16));
  EXPECT_EQ(b[0].centroid, Vec<3>(8, 8, 8));
}

}  // namespace
}  // namespace cdmpm
