// The scene parser's speed on the shape of our benchmark scenes: POV-Ray's vertex blob
// (bench/vertex_blob.cpp) is 200,000 lines `sphere { <x, y, z>, R, 1 }` with numbers of 17
// significant digits. Lexing, the core's expressions, and the whole scene through the item
// parsers, each on the same 200k-line text; the goal is well under 0.5 s for lex + parse.
//
//   build/bench/sdl_bench [--benchmark_filter=...]
#include <benchmark/benchmark.h>

#include <cstdio>
#include <random>
#include <string>

#include "sdl/lexer.hpp"
#include "sdl/parser.hpp"

namespace {

constexpr int kLines = 200000;

// `count` lines of three 17-digit coordinates in [-200, 200], as vertex_blob writes them.
std::string vertex_lines(int count, const char* format) {
  std::mt19937_64 random(1);
  std::uniform_real_distribution<double> coordinate(-200.0, 200.0);
  std::string text;
  text.reserve(size_t(count) * 80);
  char line[160];
  for (int i = 0; i < count; ++i) {
    const double x = coordinate(random), y = coordinate(random), z = coordinate(random);
    std::snprintf(line, sizeof line, format, x, y, z);
    text += line;
  }
  return text;
}

const std::string& blob_scene() {
  static const std::string text =
      "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n"
      "camera { location <0, 0, -600> look_at 0 angle 40 }\n"
      "light_source { <100, 200, -300> color rgb 1 }\n"
      "blob {\n  threshold 0.41234567890123456\n" +
      vertex_lines(kLines, "  sphere { <%.17g, %.17g, %.17g>, 2.5, 1 }\n") +
      "  pigment { color rgb 1 }\n}\n";
  return text;
}

// Only numbers and commas: 600,000 number tokens.
const std::string& number_stream() {
  static const std::string text = vertex_lines(kLines, "%.17g, %.17g, %.17g,\n");
  return text;
}

void set_bytes(benchmark::State& state, const std::string& text) {
  state.SetBytesProcessed(int64_t(state.iterations()) * int64_t(text.size()));
}

// The PEGTL lexer alone, on 600,000 numbers.
void BM_TokenizeNumbers(benchmark::State& state) {
  const std::string& text = number_stream();
  for (auto _ : state) {
    auto file = convray::sdl::tokenize("numbers.pov", text);
    benchmark::DoNotOptimize(file->tokens.data());
  }
  set_bytes(state, text);
}
BENCHMARK(BM_TokenizeNumbers)->Unit(benchmark::kMillisecond);

// Lexing plus the core's float expressions on the same numbers.
void BM_ParseNumbers(benchmark::State& state) {
  const std::string& text = number_stream();
  for (auto _ : state) {
    convray::sdl::Parser parser("numbers.pov", text, {});
    double sum = 0.0;
    for (int i = 0; i < 3 * kLines; ++i) {
      sum += parser.parse_float();
      parser.accept_comma();
    }
    benchmark::DoNotOptimize(sum);
  }
  set_bytes(state, text);
}
BENCHMARK(BM_ParseNumbers)->Unit(benchmark::kMillisecond);

// The lexer on the vertex blob scene.
void BM_TokenizeVertexBlob(benchmark::State& state) {
  const std::string& text = blob_scene();
  for (auto _ : state) {
    auto file = convray::sdl::tokenize("blob.pov", text);
    benchmark::DoNotOptimize(file->tokens.data());
  }
  set_bytes(state, text);
}
BENCHMARK(BM_TokenizeVertexBlob)->Unit(benchmark::kMillisecond);

// The whole vertex blob scene: lexing, the core and the item parsers, to a scene::Scene.
void BM_ParseVertexBlob(benchmark::State& state) {
  const std::string& text = blob_scene();
  for (auto _ : state) {
    const convray::sdl::ParseResult result =
        convray::sdl::parse_string(text, "/tmp/convray_bench/vertex_blob.pov", {});
    benchmark::DoNotOptimize(result.scene.objects.data());
  }
  set_bytes(state, text);
}
BENCHMARK(BM_ParseVertexBlob)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
