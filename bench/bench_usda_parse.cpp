// Parses .usda files repeatedly and reports throughput.
//   bench_usda_parse [-n N] [--eager] file.usda...
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "formats/usda/parser.h"

using namespace assetlint;

int main(int argc, char** argv) {
  int runs = 20;
  usda::ParseOptions options;
  std::vector<std::string> paths;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "-n" && i + 1 < argc) {
      runs = std::max(1, std::atoi(argv[++i]));
    } else if (a == "--eager") {
      options.lazy_arrays = false;
    } else {
      paths.push_back(a);
    }
  }
  if (paths.empty()) {
    std::fprintf(stderr, "usage: bench_usda_parse [-n runs] [--eager] file.usda...\n");
    return 2;
  }
  int status = 0;
  for (const auto& path : paths) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
      std::fprintf(stderr, "%s: cannot read\n", path.c_str());
      status = 2;
      continue;
    }
    std::ostringstream ss;
    ss << in.rdbuf();
    const SourceFile file(path, ss.str());
    const double mb = static_cast<double>(file.text().size()) / 1e6;
    double best = 1e30;
    double total = 0;
    std::size_t prims = 0;
    for (int r = 0; r < runs; ++r) {
      const auto t0 = std::chrono::steady_clock::now();
      const usda::ParseResult result = usda::parse_layer(file, 0, options);
      const auto t1 = std::chrono::steady_clock::now();
      if (!result.ok()) {
        const auto& e = result.error();
        std::fprintf(stderr, "%s:%u:%u: %s\n", path.c_str(), e.span.line, e.span.column, e.message.c_str());
        status = 1;
        break;
      }
      prims = result.layer().prims.size();
      const double s = std::chrono::duration<double>(t1 - t0).count();
      best = std::min(best, s);
      total += s;
    }
    if (status == 1) continue;
    std::printf("%-60s %7.3f MB  best %8.3f ms (%7.1f MB/s)  mean %8.3f ms (%7.1f MB/s)  root prims %zu\n",
                path.c_str(), mb, best * 1e3, mb / best, total / runs * 1e3, mb / (total / runs), prims);
  }
  return status;
}
