// Fuzz target: project opening. The bytes become a .mozzi file that
// ProjectStore::open (read-write, so migration and WAL set-up run too) and
// every reader then walk: summary, campaigns, hits with their sample blobs,
// FRF sets, modal results. Any input must give a value or an Error, never a
// crash, a sanitizer report or a huge allocation. Seeds: small valid projects
// (512-byte pages) holding each kind of row; see the corpus README.

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/io/project_store.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace fs = std::filesystem;
  using namespace mozzi::core::io;
  static const std::string path =
      (fs::temp_directory_path() / ("mozzi_fuzz_open_" + std::to_string(::getpid()) + ".mozzi")).string();
  auto cleanup = [] {
    std::error_code ec;
    for (const char* suffix : {"", "-wal", "-shm", "-journal"}) fs::remove(path + suffix, ec);
  };
  cleanup();
  {
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  {
    auto store = ProjectStore::open(path);
    if (store) {
      auto summary = store->summary();
      if (summary) {
        for (const auto& sp : summary->specimens) {
          (void)store->mesh(sp.id);
          auto campaigns = store->campaigns(sp.id);
          if (!campaigns) continue;
          for (const auto& c : *campaigns) {
            auto hits = store->hits(c.id);
            if (!hits) continue;
            int read = 0;
            for (const auto& h : *hits) {
              if (++read > 4) break;
              (void)store->hit(h.id);
            }
          }
        }
      }
      if (auto sets = store->frfSets()) {
        for (const auto& s : *sets) (void)store->frfSet(s.id);
      }
      if (auto results = store->modalResults()) {
        for (const auto& r : *results) (void)store->modalResult(r.id);
      }
      for (std::int64_t id = 1; id <= 2; ++id) {
        (void)store->rigSetup(id);
        (void)store->rigTest(id);
        (void)store->rigTestRecord(id, 0);
        (void)store->tyreTest(id);
        (void)store->tyreTestRecord(id, 0);
        (void)store->analysis(id);
      }
      (void)store->rigTests();
      (void)store->tyreTests();
    }
  }
  cleanup();
  return 0;
}
