// Reading a stored FRF set back (ProjectStore::frfSet): the first page that
// shows a set pays it on the GUI thread (FRF, Identification, Mode Animation;
// WORKBENCH.md's 50 ms budget for opening a page). The set is the demo
// frame's shape: 3 accelerometers x 60 hammer points x 3201 lines (9.2 MB of
// FRFs), and a 100 x 1 x 20,000 one as in issue 19.
//
//   build/test/tests/project_read_bench --benchmark_min_time=1
//
// Each iteration reads the whole set: SQL, checksums, decoding into the
// matrices; the file is in the page cache after the first iteration.

#include <benchmark/benchmark.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "core/io/project_store.h"
#include "synthetic_frfs.h"

namespace {

namespace fs = std::filesystem;
using namespace mozzi::core;
using namespace mozzi::core::io;

void readFrfSet(benchmark::State& state) {
  const int responses = static_cast<int>(state.range(0));
  const int references = static_cast<int>(state.range(1));
  const int lines = static_cast<int>(state.range(2));
  const fs::path dir = fs::temp_directory_path() / ("mozzi_bench_read_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  {
    auto store = ProjectStore::create((dir / "bench.mozzi").string(), "bench");
    if (!store) {
      state.SkipWithError(store.error().describe().c_str());
      return;
    }
    const FrfMatrix frf = modal::bench::syntheticFrfs(responses, lines, 0.25, references);
    auto specimen = store->addSpecimen("Frame A", "frame", "");
    FrfSetInfo info;
    info.specimenId = *specimen;
    info.name = "bench";
    auto id = store->addFrfSet(info, frf, {});
    if (!id) {
      state.SkipWithError(id.error().describe().c_str());
      return;
    }
    for (auto _ : state) {
      auto read = store->frfSet(*id);
      if (!read) {
        state.SkipWithError(read.error().describe().c_str());
        break;
      }
      benchmark::DoNotOptimize(read->h.data());
    }
    state.SetBytesProcessed(state.iterations() * std::int64_t{responses} * references * lines * 16);
  }
  fs::remove_all(dir);
}
// Args: responses, references, lines.
BENCHMARK(readFrfSet)->Args({3, 60, 3201})->Args({100, 1, 20000})->Unit(benchmark::kMillisecond);

}  // namespace
