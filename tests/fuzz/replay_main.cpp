// Replay driver for fuzz targets when the build is not a libFuzzer build
// (gcc, or MOZZI_BUILD_FUZZERS off): feeds every file of the given corpus
// folders to LLVMFuzzerTestOneInput, then a bounded number of deterministic
// mutations of them (bit flips, truncations, byte insertions, splices), so the
// ordinary test run exercises each parser on hostile input. A crash or a
// sanitizer report fails the test; the seed makes any failure reproducible.

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

std::vector<std::uint8_t> readFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void runOne(const std::vector<std::uint8_t>& input) {
  // Copy into an exactly-sized heap buffer so ASan catches reads past the end.
  std::vector<std::uint8_t> copy(input);
  LLVMFuzzerTestOneInput(copy.empty() ? nullptr : copy.data(), copy.size());
}

std::vector<std::uint8_t> mutate(const std::vector<std::uint8_t>& seed, const std::vector<std::uint8_t>& other,
                                 std::mt19937_64& rng) {
  std::vector<std::uint8_t> out = seed;
  auto pick = [&](std::size_t n) { return n == 0 ? std::size_t{0} : static_cast<std::size_t>(rng() % n); };
  const int edits = 1 + static_cast<int>(rng() % 8);
  for (int e = 0; e < edits; ++e) {
    switch (rng() % 6) {
      case 0:  // flip a bit
        if (!out.empty()) out[pick(out.size())] ^= static_cast<std::uint8_t>(1u << (rng() % 8));
        break;
      case 1:  // truncate
        out.resize(pick(out.size() + 1));
        break;
      case 2: {  // insert a byte that often matters to text parsers
        static const char kInteresting[] = "-1 9e999\n\r.\0E+ ";
        out.insert(out.begin() + static_cast<std::ptrdiff_t>(pick(out.size() + 1)),
                   static_cast<std::uint8_t>(kInteresting[pick(sizeof(kInteresting) - 1)]));
        break;
      }
      case 3:  // overwrite with a random byte
        if (!out.empty()) out[pick(out.size())] = static_cast<std::uint8_t>(rng());
        break;
      case 4: {  // splice a piece of another seed
        if (other.empty()) break;
        const std::size_t from = pick(other.size());
        const std::size_t len = pick(std::min<std::size_t>(other.size() - from, 256) + 1);
        const std::size_t at = pick(out.size() + 1);
        out.insert(out.begin() + static_cast<std::ptrdiff_t>(at), other.begin() + static_cast<std::ptrdiff_t>(from),
                   other.begin() + static_cast<std::ptrdiff_t>(from + len));
        break;
      }
      default: {  // replace a digit run with a huge number
        static const char kHuge[] = "999999999999";
        const std::size_t at = pick(out.size() + 1);
        out.insert(out.begin() + static_cast<std::ptrdiff_t>(at), kHuge, kHuge + sizeof(kHuge) - 1);
        break;
      }
    }
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  long mutations = 0;
  std::uint64_t seed = 20261121;
  std::vector<std::vector<std::uint8_t>> corpus;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg.rfind("--mutations=", 0) == 0) {
      mutations = std::strtol(arg.c_str() + 12, nullptr, 10);
    } else if (arg.rfind("--seed=", 0) == 0) {
      seed = std::strtoull(arg.c_str() + 7, nullptr, 10);
    } else if (std::filesystem::is_directory(arg)) {
      for (const auto& entry : std::filesystem::recursive_directory_iterator(arg)) {
        if (entry.is_regular_file()) corpus.push_back(readFile(entry.path()));
      }
    } else if (std::filesystem::is_regular_file(arg)) {
      corpus.push_back(readFile(arg));
    } else {
      std::fprintf(stderr, "replay: '%s' is neither an option, a folder nor a file\n", argv[i]);
      return 2;
    }
  }
  if (corpus.empty()) {
    std::fprintf(stderr, "replay: empty corpus; give at least one seed file or folder\n");
    return 2;
  }
  runOne({});
  for (const auto& input : corpus) runOne(input);
  std::mt19937_64 rng(seed);
  for (long m = 0; m < mutations; ++m) {
    const auto& a = corpus[rng() % corpus.size()];
    const auto& b = corpus[rng() % corpus.size()];
    runOne(mutate(a, b, rng));
  }
  std::printf("replay: %zu seeds and %ld mutations ran without a crash (seed %llu)\n", corpus.size(), mutations,
              static_cast<unsigned long long>(seed));
  return 0;
}
