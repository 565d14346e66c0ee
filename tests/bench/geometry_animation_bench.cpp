// Mode-shape animation, the numerics side: what one animation tick costs on a
// 20,000-node mesh (the deformed points and magnitudes from two warp scales),
// and what the once-per-shape work costs (spreading a shape measured at one
// node in ten over the mesh by trace-line interpolation, the colour range).
// The render itself is timed by the GUI test
// (tests/views/scene/mode_animation_view_test.cpp); docs/performance/scene.md
// has both figures and the commands.

#include <benchmark/benchmark.h>

#include <cmath>

#include "core/geometry/animation.h"
#include "core/geometry/mode_shape.h"

namespace {

using namespace mozzi::core;

// A plate of nx x ny nodes, 5 mm apart, trace lines along both directions.
io::MeshDocument plate(int nx, int ny) {
  io::MeshDocument d;
  d.mesh.nodes.reserve(static_cast<std::size_t>(nx * ny));
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      io::StoredNode n;
      n.label = 1 + i + nx * j;
      n.position = Vector3(0.005 * i, 0.005 * j, 0.0);
      d.mesh.nodes.push_back(n);
      if (i > 0) d.mesh.lines.push_back({n.label - 1, n.label});
      if (j > 0) d.mesh.lines.push_back({n.label - nx, n.label});
    }
  return d;
}

// First bending-like shape sampled on every tenth node in z.
void measured(const io::MeshDocument& d, int nx, std::vector<Dof>& dofs, ComplexVector& values) {
  std::vector<Complex> v;
  for (const auto& n : d.mesh.nodes) {
    const int i = (n.label - 1) % nx, j = (n.label - 1) / nx;
    if (i % 10 != 0 || j % 10 != 0) continue;
    dofs.push_back(Dof{n.label, Direction::Z, false});
    v.push_back(Complex(std::sin(M_PI * i / (nx - 1)) * std::sin(M_PI * j / 99.0), 0.1 * i / nx));
  }
  values = Eigen::Map<ComplexVector>(v.data(), static_cast<Eigen::Index>(v.size()));
}

// The 20,000-node plate with its shape spread and split once, as a view holds them.
struct Plate20k {
  geometry::ShapeField field;
  geometry::NodePoints base, re, im;
};
Plate20k plate20k() {
  const int nx = 200, ny = 100;
  const auto d = plate(nx, ny);
  std::vector<Dof> dofs;
  ComplexVector values;
  measured(d, nx, dofs, values);
  Plate20k p;
  p.field = geometry::shapeField(d, dofs, values).value();
  p.base = geometry::nodePoints(d.mesh).value();
  p.re = geometry::realPart(p.field.u);
  p.im = geometry::imagPart(p.field.u);
  return p;
}

// A tick as it was: the points and a magnitude per node.
void BM_AnimationTick20k(benchmark::State& state) {
  const Plate20k p = plate20k();
  geometry::NodePoints out(p.base.rows(), 3);
  Vector magnitude(p.base.rows());
  double t = 0.0;
  for (auto _ : state) {
    t += 1.0 / 30.0;
    const auto s = geometry::warpScales(0.01, geometry::animationPhase(t, 0.5));
    geometry::deformPoints(p.base, p.re, p.im, s, out, &magnitude);
    benchmark::DoNotOptimize(out.data());
    benchmark::DoNotOptimize(magnitude.data());
  }
  state.SetItemsProcessed(state.iterations() * p.base.rows());
}
BENCHMARK(BM_AnimationTick20k)->Unit(benchmark::kMicrosecond);

// What a tick does now (scene_view.cpp): the points only, one fused loop;
// the colours were set once per shape (BM_ColourValues20k).
void BM_AnimationTickPoints20k(benchmark::State& state) {
  const Plate20k p = plate20k();
  geometry::NodePoints out(p.base.rows(), 3);
  double t = 0.0;
  for (auto _ : state) {
    t += 1.0 / 30.0;
    const auto s = geometry::warpScales(0.01, geometry::animationPhase(t, 0.5));
    geometry::deformPoints(p.base.data(), p.re.data(), p.im.data(), p.base.rows(), s, out.data());
    benchmark::DoNotOptimize(out.data());
  }
  state.SetItemsProcessed(state.iterations() * p.base.rows());
}
BENCHMARK(BM_AnimationTickPoints20k)->Unit(benchmark::kMicrosecond);

// Once per shape and amplitude: each node's peak displacement, the value it is coloured by.
void BM_ColourValues20k(benchmark::State& state) {
  const Plate20k p = plate20k();
  for (auto _ : state) {
    Vector c = geometry::colourValues(p.field.u, 0.01);
    benchmark::DoNotOptimize(c.data());
  }
  state.SetItemsProcessed(state.iterations() * p.field.u.rows());
}
BENCHMARK(BM_ColourValues20k)->Unit(benchmark::kMicrosecond);

void BM_ShapeFieldInterpolated20k(benchmark::State& state) {
  const int nx = 200, ny = 100;
  const auto d = plate(nx, ny);
  std::vector<Dof> dofs;
  ComplexVector values;
  measured(d, nx, dofs, values);
  for (auto _ : state) {
    auto field = geometry::shapeField(d, dofs, values);
    benchmark::DoNotOptimize(field);
  }
}
BENCHMARK(BM_ShapeFieldInterpolated20k)->Unit(benchmark::kMillisecond);

}  // namespace
