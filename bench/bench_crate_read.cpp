// Reads binary USD (crate) layers repeatedly and compares with reading the same layer as
// USDA text. crate: what checking a crate layer costs (usdc::read_crate_layer, the layer
// built from the crate's specs); via_text: the crate written as the USDA `cat` prints,
// then parsed; usda: the parse of that same text (what a .usda file of the same content
// costs). --crate-only times the crate read alone (to profile it with perf).
//   bench_crate_read [-n N] [--crate-only] file.usd...
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include "formats/usda/parser.h"
#include "formats/usdc/crate_layer.h"
#include "formats/usdc/crate_usda.h"

using namespace assetlint;

namespace {

std::size_t count_prims(const std::vector<usda::Prim>& prims) {
  std::size_t n = prims.size();
  for (const auto& p : prims) n += count_prims(p.children);
  return n;
}

template <class Fn>
double best_of(int runs, Fn&& fn) {
  double best = runs > 0 ? 1e30 : 0.0;
  for (int r = 0; r < runs; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    fn();
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  int runs = 20;
  bool crate_only = false;
  std::vector<std::string> paths;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "-n" && i + 1 < argc) runs = std::max(1, std::atoi(argv[++i]));
    else if (a == "--crate-only") crate_only = true;
    else paths.push_back(a);
  }
  if (paths.empty()) {
    std::fprintf(stderr, "usage: bench_crate_read [-n runs] [--crate-only] file.usd...\n");
    return 2;
  }
  std::printf("file\tcrate_bytes\tusda_bytes\tprims\tcrate_ms\tvia_text_ms\tusda_ms\tcrate_us_per_prim\tusda_us_per_prim\n");
  for (const auto& path : paths) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    const std::string bytes = ss.str();
    auto first = usdc::crate_to_usda(bytes);
    if (auto* e = std::get_if<usdc::CrateError>(&first)) {
      std::fprintf(stderr, "%s\n", usdc::describe(*e, path).c_str());
      return 1;
    }
    const std::string text = std::get<usdc::CrateText>(first).text;
    std::size_t prims = 0;
    const double crate = best_of(runs, [&] {
      std::string error;
      auto read = usdc::read_crate_layer(path, bytes, 0, error);
      if (!read || !read->layer) {
        std::fprintf(stderr, "%s: not read directly %s\n", path.c_str(), error.c_str());
        std::abort();
      }
      prims = count_prims(read->layer->prims);
    });
    const int other_runs = crate_only ? 0 : runs;
    const double via_text = best_of(other_runs, [&] {
      auto r = usdc::crate_to_usda(bytes);
      const SourceFile file(path, std::move(std::get<usdc::CrateText>(r).text));
      if (!usda::parse_layer(file, 0).ok()) std::abort();
    });
    const double usda = best_of(other_runs, [&] {
      const SourceFile file(path, text);
      auto parsed = usda::parse_layer(file, 0);
      if (!parsed.ok()) std::abort();
    });
    const double per = static_cast<double>(std::max<std::size_t>(prims, 1));
    std::printf("%s\t%zu\t%zu\t%zu\t%.3f\t%.3f\t%.3f\t%.2f\t%.2f\n", path.c_str(), bytes.size(), text.size(), prims,
                crate * 1e3, via_text * 1e3, usda * 1e3, crate * 1e6 / per, usda * 1e6 / per);
  }
  return 0;
}
