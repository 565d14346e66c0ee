// Whole commands (issue 19): `identify`, `frf` and `uff info` run in-process
// through the CLI dispatcher on generated files, the way a user runs them but
// without process start-up (scripts/bench-cli.sh times the processes,
// start-up included). Also the step behind a click in the stabilization
// diagram (LSFD + synthesis for a chosen pole set) on the ModeLAB beam.
//
// Files (generated once into $MOZZI_BENCH_DIR, default /tmp/mozzi_bench_cli):
//   identify_100x20000.uff  100 accelerances x 20,000 lines (0.1 .. 2000 Hz),
//                           one reference, 20 modes at 80 + 90 r Hz, zeta
//                           0.005 + 0.001 r, random real shapes (seed 3), 1%
//                           complex noise: the data of modal_plscf_bench; 58b
//                           complex double (32 MB of FRF data)
//   identify_10x5000.uff    the first 10 responses on 5,000 lines (0.2 .. 1000 Hz)
//   hits_10x4x65536.uff     10 hammer hits x (force + 3 accelerations) x 65,536
//                           samples at 8192 Hz, 3-DOF system, 58b real double (21 MB)
// `cli_commands_bench --write-files` writes them and exits (for the script).
// Counters: for identify, the largest relative frequency and damping errors
// of the identified modes against the generating ones (band 50-950 Hz).
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "app/cli/command.h"
#include "core/io/uff/uff.h"
#include "core/io/uff_hits.h"
#include "core/modal/identification.h"
#include "core/modal/modal_model.h"
#include "core/signal/hit_quality.h"
#include "core/signal/hit_synthesis.h"
#include "modelab_beam.h"
#include "synthetic_frfs.h"

namespace {

namespace fs = std::filesystem;
namespace uff = mozzi::core::io::uff;
namespace md = mozzi::core::modal;
namespace sg = mozzi::core::signal;
using mozzi::core::Complex;
using mozzi::core::Direction;
using mozzi::core::Dof;
using mozzi::core::FrfMatrix;
using mozzi::core::FrfType;

double trueFrequency(int r) {
  return md::bench::syntheticFrequencyHz(r);
}
double trueZeta(int r) {
  return md::bench::syntheticZeta(r);
}

fs::path dir() {
  const char* env = std::getenv("MOZZI_BENCH_DIR");
  return env ? fs::path(env) : fs::temp_directory_path() / "mozzi_bench_cli";
}

// Accelerances of the 20-mode system of synthetic_frfs.h at `no` responses
// on nf lines from df to nf df.
FrfMatrix syntheticFrfs(int no, int nf, double df) {
  return md::bench::syntheticFrfs(no, nf, df);
}

void writeFrfs(const FrfMatrix& frf, const fs::path& path) {
  auto records = uff::fromFrfMatrix(frf);
  if (!records) throw std::runtime_error(records.error().describe());
  uff::UffFile file;
  for (auto& r : *records) {
    r.binary = true;
    file.datasets.push_back(uff::makeDataset(std::move(r)));
  }
  if (auto ok = uff::writeFile(path.string(), file); !ok) throw std::runtime_error(ok.error().describe());
}

void writeHits(const fs::path& path) {
  sg::LinearMdof s;
  s.mass = Eigen::Vector3d(1.0, 0.7, 0.5).asDiagonal();
  s.stiffness.resize(3, 3);
  s.stiffness << 2.0e5, -8e4, 0.0, -8e4, 1.6e5, -8e4, 0.0, -8e4, 8e4;
  s.damping = 1e-4 * s.stiffness + 2.0 * s.mass;
  uff::UffFile file;
  for (int h = 1; h <= 10; ++h) {
    sg::HammerHitSpec spec;
    spec.sampleRateHz = 8192.0;
    spec.sampleCount = 65536;
    spec.oversampling = 4;
    spec.pulseWidthS = 2e-3;
    spec.peakForceN = 90.0 + 2.0 * h;
    spec.forceNoiseRms = 0.02;
    spec.responseNoiseRms = 0.002;
    spec.seed = static_cast<std::uint64_t>(h);
    auto rec = sg::synthesizeHammerHit(s, spec);
    if (!rec) throw std::runtime_error(rec.error().describe());
    for (Eigen::Index c = 0; c < rec->channelCount(); ++c) {
      uff::Function58 f;
      f.idLines = {"hit " + std::to_string(h), "synthetic", "NONE", "NONE", "NONE"};
      f.functionType = uff::FunctionType::TimeResponse;
      f.functionId = static_cast<int>(c + 1);
      f.loadCase = h;
      f.response = uff::Channel58::fromDof(rec->channels[static_cast<std::size_t>(c)].dof);
      f.ordinateType = uff::OrdinateType::RealDouble;
      f.abscissaMin = -static_cast<double>(rec->preTriggerSamples) / rec->sampleRateHz;
      f.abscissaIncrement = 1.0 / rec->sampleRateHz;
      f.abscissaAxis.specificDataType = 17;
      const bool force = rec->channels[static_cast<std::size_t>(c)].transducer.kind == sg::TransducerKind::Force;
      f.ordinateNumerator.specificDataType = force ? 13 : 12;
      f.ordinateNumerator.unitsLabel = force ? "N" : "m/s^2";
      f.real = rec->samples.col(c);
      f.binary = true;
      file.datasets.push_back(uff::makeDataset(std::move(f)));
    }
  }
  if (auto ok = uff::writeFile(path.string(), file); !ok) throw std::runtime_error(ok.error().describe());
}

std::string file(const std::string& name) {
  const fs::path p = dir() / name;
  if (fs::exists(p)) return p.string();
  fs::create_directories(dir());
  // A name of its own: two benchmark runs (e.g. ctest -j) may write at once.
  const fs::path tmp = p.string() + "." + std::to_string(::getpid()) + ".part";
  if (name == "identify_100x20000.uff") {
    writeFrfs(syntheticFrfs(100, 20000, 0.1), tmp);
  } else if (name == "identify_10x5000.uff") {
    writeFrfs(syntheticFrfs(10, 5000, 0.2), tmp);
  } else if (name == "hits_10x4x65536.uff") {
    writeHits(tmp);
  } else {
    throw std::runtime_error("unknown bench file " + name);
  }
  fs::rename(tmp, p);
  return p.string();
}

int runCommand(const std::vector<std::string>& args, std::string* output = nullptr) {
  std::ostringstream out, err;
  const int code = mozzi::cli::runCli(args, out, err);
  if (code != 0) std::fprintf(stderr, "%s", err.str().c_str());
  if (output) *output = out.str();
  return code;
}

// Largest relative errors of the identified modes against the generating ones.
void accuracy(benchmark::State& state, const std::string& json) {
  const auto j = nlohmann::json::parse(json);
  double fErr = 0.0, zErr = 0.0;
  for (const auto& m : j["modes"]) {
    const double f = m["frequency_hz"], z = m["zeta"];
    const int r = static_cast<int>(std::lround((f - 80.0) / 90.0));
    fErr = std::max(fErr, std::abs(f - trueFrequency(r)) / trueFrequency(r));
    zErr = std::max(zErr, std::abs(z - trueZeta(r)) / trueZeta(r));
  }
  state.counters["modes"] = static_cast<double>(j["modes"].size());
  state.counters["f_rel_err"] = fErr;
  state.counters["zeta_rel_err"] = zErr;
}

void runIdentify(benchmark::State& state, const std::string& name) {
  const std::string path = file(name);
  std::string out;
  for (auto _ : state) {
    if (runCommand({"identify", path, "--band", "50:950", "--max-order", "60", "--json"}, &out) != 0) {
      state.SkipWithError("identify failed");
      return;
    }
  }
  accuracy(state, out);
}

void BM_Identify_100x20000(benchmark::State& state) {
  runIdentify(state, "identify_100x20000.uff");
}
BENCHMARK(BM_Identify_100x20000)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_Identify_10x5000(benchmark::State& state) {
  runIdentify(state, "identify_10x5000.uff");
}
BENCHMARK(BM_Identify_10x5000)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_Frf_H1_10hits(benchmark::State& state) {
  const std::string path = file("hits_10x4x65536.uff");
  for (auto _ : state) {
    if (runCommand({"frf", path, "--estimator", "H1"}) != 0) {
      state.SkipWithError("frf failed");
      return;
    }
  }
}
BENCHMARK(BM_Frf_H1_10hits)->Unit(benchmark::kMillisecond)->UseRealTime();

// The streaming read the frf target is measured against: `uff info` of the same file.
void BM_UffInfo_Hits(benchmark::State& state) {
  const std::string path = file("hits_10x4x65536.uff");
  for (auto _ : state) {
    if (runCommand({"uff", "info", path}) != 0) {
      state.SkipWithError("uff info failed");
      return;
    }
  }
}
BENCHMARK(BM_UffInfo_Hits)->Unit(benchmark::kMillisecond)->UseRealTime();

// The stages of `frf` on the thread that reads (issue 19): the hits streamed
// from the file (UffHitReader, what `uff info` costs plus the sample matrices),
// and the check of each hit (assessHit) on hits already in memory.
void BM_FrfStage_ReadHits(benchmark::State& state) {
  const std::string path = file("hits_10x4x65536.uff");
  for (auto _ : state) {
    auto reader = mozzi::core::io::UffHitReader::open(path);
    int hits = 0;
    for (;;) {
      auto hit = reader->next();
      if (!hit) {
        state.SkipWithError(hit.error().describe().c_str());
        return;
      }
      if (!*hit) break;
      ++hits;
    }
    benchmark::DoNotOptimize(hits);
  }
}
BENCHMARK(BM_FrfStage_ReadHits)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_FrfStage_AssessHits(benchmark::State& state) {
  std::vector<sg::TimeRecord> records;
  auto reader = mozzi::core::io::UffHitReader::open(file("hits_10x4x65536.uff"));
  for (auto hit = reader->next(); hit && *hit; hit = reader->next()) records.push_back((*hit)->record);
  for (auto _ : state) {
    for (const auto& r : records) {
      auto q = sg::assessHit(r, sg::HitQualityOptions{});
      benchmark::DoNotOptimize(q);
    }
  }
  state.counters["hits"] = static_cast<double>(records.size());
}
BENCHMARK(BM_FrfStage_AssessHits)->Unit(benchmark::kMillisecond)->UseRealTime();

// A click in the stabilization diagram of the ModeLAB beam (9 FRFs x 47,872
// lines, 65-1000 Hz): the automatically selected poles with one pole removed,
// LSFD + synthesis of every FRF on the band (target: 50 ms).
const FrfMatrix& modelabBeam() {
  return md::bench::modelabBeam();
}

void BM_PoleClick_Beam(benchmark::State& state) {
  const FrfMatrix& beam = modelabBeam();
  md::IdentificationOptions opt;
  opt.estimator.bandLowHz = 65.0;
  opt.estimator.bandHighHz = 1000.0;
  opt.estimator.maxOrder = 60;
  opt.refine = false;
  auto id = md::identifyModes(beam, opt);
  if (!id) {
    state.SkipWithError(id.error().describe().c_str());
    return;
  }
  std::vector<Complex> poles;
  for (const auto& s : id->selected) poles.push_back(s.pole);
  if (poles.size() > 1) poles.pop_back();  // the user drops the last pole
  md::LsfdOptions band;
  band.bandLowHz = 65.0;
  band.bandHighHz = 1000.0;
  double err = 0.0;
  for (auto _ : state) {
    auto fit = md::fitSelectedPoles(beam, poles, band);
    if (!fit) {
      state.SkipWithError(fit.error().describe().c_str());
      return;
    }
    err = fit->relativeError;
    benchmark::DoNotOptimize(fit->synthesis.h.front().data());
  }
  state.counters["poles"] = static_cast<double>(poles.size());
  state.counters["rel_err"] = err;
}
BENCHMARK(BM_PoleClick_Beam)->Unit(benchmark::kMillisecond)->UseRealTime();

// The full result for the new selection (reselectModes: LSFD + refinement
// with standard errors, the diagram kept) after the same click: the diagram
// poles of the highest order nearest to the automatic selection, the last
// one dropped.
void BM_Reselect_Beam(benchmark::State& state) {
  const FrfMatrix& beam = modelabBeam();
  md::IdentificationOptions opt;
  opt.estimator.bandLowHz = 65.0;
  opt.estimator.bandHighHz = 1000.0;
  opt.estimator.maxOrder = 60;
  auto id = md::identifyModes(beam, opt);
  if (!id) {
    state.SkipWithError(id.error().describe().c_str());
    return;
  }
  const auto& poles = id->diagram.poles;
  std::vector<std::size_t> picks;
  for (const auto& s : id->selected) {
    std::size_t best = poles.size();
    for (std::size_t i = 0; i < poles.size(); ++i) {
      if (poles[i].order != id->diagram.orders.back()) continue;
      if (best == poles.size() || std::abs(poles[i].pole - s.pole) < std::abs(poles[best].pole - s.pole)) best = i;
    }
    if (best < poles.size()) picks.push_back(best);
  }
  if (picks.size() > 1) picks.pop_back();
  md::IdentificationResult last;
  for (auto _ : state) {
    auto r = md::reselectModes(beam, id->diagram, picks, opt);
    if (!r) {
      state.SkipWithError(r.error().describe().c_str());
      return;
    }
    last = std::move(r).value();
  }
  state.counters["modes"] = static_cast<double>(last.model().modes.size());
  state.counters["iterations"] = last.refined ? last.refined->iterations : 0;
}
BENCHMARK(BM_Reselect_Beam)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

int main(int argc, char** argv) {
  if (argc >= 2 && std::string(argv[1]) == "--write-files") {
    for (const char* n : {"identify_100x20000.uff", "identify_10x5000.uff", "hits_10x4x65536.uff"}) {
      std::printf("%s\n", file(n).c_str());
    }
    return 0;
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
