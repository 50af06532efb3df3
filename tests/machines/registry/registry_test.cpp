// The controller registry: every controller reads a program held in memory (open_text, which the
// fuzz target `controllers` drives) exactly as it reads the same program from a file (open).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "machines/registry/registry.hpp"
#include "toolpath/error.hpp"
#include "toolpath/trace_writer.hpp"

namespace {

std::string trace_of(machines::ProgramSource& source) {
  std::ostringstream out;
  toolpath::TraceWriter writer(out);
  toolpath::Command c;
  while (source.next(c)) writer.write(c);
  writer.flush();
  return out.str();
}

TEST(Registry, EveryControllerReadsFromMemoryAsFromAFile) {
  const auto dir = std::filesystem::temp_directory_path() / "postproc-registry-test";
  std::filesystem::create_directories(dir);
  for (const machines::Controller* c : machines::controllers()) {
    const std::string name(c->names().front());
    SCOPED_TRACE(name);
    std::ostringstream program;
    ASSERT_TRUE(c->write_sample_program(program, 40));
    const auto path = dir / (name + ".nc");
    std::ofstream(path, std::ios::binary) << program.str();
    machines::ReadOptions options;
    options.nc_lines_in_trace = true;
    std::ostringstream file_warnings, text_warnings;
    const std::string from_file = trace_of(*c->open(path.string(), name, options, file_warnings));
    const std::string from_text = trace_of(*c->open_text(program.str(), path.string(), name, options, text_warnings));
    EXPECT_GT(from_file.size(), 1000u);
    EXPECT_EQ(from_text, from_file);
    EXPECT_EQ(text_warnings.str(), file_warnings.str());
  }
  std::filesystem::remove_all(dir);
}

// A low block bound stops a runaway loop with an error instead of running it for minutes.
TEST(Registry, MaxBlocksBoundsALoop) {
  struct Case {
    const char* dialect;
    const char* program;
  } cases[] = {
      {"fanuc", "%\nO1\n#1=0\nWHILE [#1 LT 1] DO1\nG0 X1\nEND1\nM30\n%\n"},
      {"sinumerik", "N10 LOOP: G0 X1\nN20 GOTOB LOOP\nN30 M30\n"},
  };
  for (const auto& k : cases) {
    SCOPED_TRACE(k.dialect);
    machines::ReadOptions options;
    options.max_blocks = 100;
    std::ostringstream warnings;
    auto source = machines::find_controller(k.dialect)->open_text(k.program, "loop.nc", k.dialect, options, warnings);
    EXPECT_THROW(trace_of(*source), toolpath::InputError);
  }
}

}  // namespace
