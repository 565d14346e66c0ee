#pragma once
// The real-data worked example of docs/gap.md (issue 16): the free-free beam
// of ModeLAB (shared/data/modelab-beam, nine roving-hammer accelerances, the
// accelerometer at hammer position 4) against a model built from its geometry.
//
// Model: Euler-Bernoulli beam, length 1.3 m (the README's reading of the
// symmetric layout), 20 cubic Hermite elements with consistent mass (nodes at
// the nine hammer positions, the two ends and the midpoint of every span),
// translation X and rotation RY per node, free-free (no supports: the rubber
// bands of a free-free test are far below the band). The source does not
// state the section or the material: the nominal is a solid steel bar 40 mm
// deep in bending and 25 mm wide (E = 210 GPa, rho = 7850 kg/m^3; first
// bending mode 126 Hz, mass 10.2 kg), and the model's own uncertain parameters
// are a scale on EI ("stiffness"), a scale on rho A ("mass"), both 0.25 to 4
// without prior, and a scale on the modal damping (nominal 0.1%, 0.01 to 10).
// Hammer node i (1..9) is DOF "i+X"; the other nodes are 100 + their index.

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/common/dof.h"
#include "core/common/frf_matrix.h"
#include "core/gap/structural/model_file.h"
#include "core/io/modelab_ascii.h"

namespace mozzi::gap_bench {

inline const double kBeamHammerZ[9] = {0.1, 0.25, 0.375, 0.5, 0.65, 0.8, 0.925, 1.05, 1.2};  // setup.csv, m
constexpr double kBeamLength = 1.3;

inline core::gap::structural::StructuralModel modelabBeamModel() {
  using core::Matrix;
  // Nodes: ends, hammer positions, midpoints of every span between them.
  std::vector<double> key{0.0};
  for (double z : kBeamHammerZ) key.push_back(z);
  key.push_back(kBeamLength);
  std::vector<double> z;
  std::vector<int> id;
  for (std::size_t i = 0; i < key.size(); ++i) {
    if (i > 0) {
      z.push_back(0.5 * (key[i - 1] + key[i]));
      id.push_back(100 + static_cast<int>(z.size()));
    }
    z.push_back(key[i]);
    const bool hammer = i >= 1 && i <= 9;
    id.push_back(hammer ? static_cast<int>(i) : 100 + static_cast<int>(z.size()));
  }
  const double e = 210e9, rho = 7850.0, depth = 0.040, width = 0.025;
  const double ei = e * width * depth * depth * depth / 12.0, rhoA = rho * width * depth;
  const int nodes = static_cast<int>(z.size()), n = 2 * nodes;
  core::gap::structural::StructuralModel m;
  m.name = "ModeLAB free-free beam (Euler-Bernoulli, 1.3 m, nominal 40 x 25 mm steel)";
  for (int i = 0; i < nodes; ++i) {
    for (const auto dir : {core::Direction::X, core::Direction::RY}) {
      const core::Dof d{id[static_cast<std::size_t>(i)], dir, false};
      m.dofs.push_back(d);
      m.labels.push_back(core::gap::structural::modelDofLabel(d));
    }
  }
  m.t = Matrix::Identity(n, n);
  m.m = Matrix::Zero(n, n);
  m.k = Matrix::Zero(n, n);
  for (int el = 0; el + 1 < nodes; ++el) {
    const double l = z[static_cast<std::size_t>(el + 1)] - z[static_cast<std::size_t>(el)];
    // Hermite beam element (w1, theta1, w2, theta2).
    Eigen::Matrix4d k, mm;
    k << 12, 6 * l, -12, 6 * l, 6 * l, 4 * l * l, -6 * l, 2 * l * l, -12, -6 * l, 12, -6 * l, 6 * l, 2 * l * l, -6 * l,
        4 * l * l;
    k *= ei / (l * l * l);
    mm << 156, 22 * l, 54, -13 * l, 22 * l, 4 * l * l, 13 * l, -3 * l * l, 54, 13 * l, 156, -22 * l, -13 * l,
        -3 * l * l, -22 * l, 4 * l * l;
    mm *= rhoA * l / 420.0;
    m.k.block(2 * el, 2 * el, 4, 4) += k;
    m.m.block(2 * el, 2 * el, 4, 4) += mm;
  }
  m.modalDamping = core::Vector::Constant(n, 0.001);
  m.parameters.push_back({"ei_scale", {"stiffness"}, 1.0, 0.25, 4.0, 0.0});
  m.parameters.push_back({"rho_a_scale", {"mass"}, 1.0, 0.25, 4.0, 0.0});
  m.parameters.push_back({"damping_scale", {"damping"}, 1.0, 0.01, 10.0, 0.0});
  return m;
}

// The nine measured accelerances, stored by reciprocity with the accelerometer
// (hammer position 4, along -X in setup.csv, expressed along +X) as the
// reference, every `step`-th line in [lowHz, highHz].
inline core::Result<core::FrfMatrix> modelabBeamFrfs(int step, double lowHz, double highHz) {
  const std::string dir = std::string(MOZZI_SHARED_DATA_DIR) + "/modelab-beam/SignalCalc/";
  std::vector<std::string> files;
  std::vector<core::Dof> hammers;
  for (int i = 1; i <= 9; ++i) {
    char name[64];
    std::snprintf(name, sizeof name, "ASCII%05d/Hxysv%05d.txt", i, i);
    files.push_back(dir + name);
    hammers.push_back(core::Dof{i, core::Direction::X, false});
  }
  auto frf = core::io::readSignalCalcRovingHammer(files, hammers, core::Dof{4, core::Direction::X, true},
                                                  core::FrfType::Accelerance);
  if (!frf) return frf.error();
  frf->references[0] = core::Dof{4, core::Direction::X, false};
  frf->h[0] = -frf->h[0];
  std::vector<Eigen::Index> keep;
  for (Eigen::Index k = 0; k < frf->lineCount(); k += step)
    if (frf->frequencyHz[k] >= lowHz && frf->frequencyHz[k] <= highHz) keep.push_back(k);
  core::FrfMatrix out;
  out.type = frf->type;
  out.responses = frf->responses;
  out.references = frf->references;
  out.frequencyHz.resize(static_cast<Eigen::Index>(keep.size()));
  out.h.assign(1, core::ComplexMatrix(static_cast<Eigen::Index>(keep.size()), frf->responseCount()));
  for (std::size_t j = 0; j < keep.size(); ++j) {
    out.frequencyHz[static_cast<Eigen::Index>(j)] = frf->frequencyHz[keep[j]];
    out.h[0].row(static_cast<Eigen::Index>(j)) = frf->h[0].row(keep[j]);
  }
  return out;
}

}  // namespace mozzi::gap_bench
