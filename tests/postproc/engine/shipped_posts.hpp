// The posts we ship and the example jobs, as the engine tests run them (from tests/, as ctest
// does): every machine below with every job gives the tests of the whole engine their spread.
#pragma once

#include <string>
#include <vector>

#include "postproc/engine/engine.hpp"

namespace engine_test {

inline const std::vector<std::string> kShippedMachines{"fanuc", "linuxcnc", "mill-turn", "sinumerik", "wire-edm"};

inline const std::vector<std::string> kExampleJobs{
    "../docs/examples/drill-cycles.trace",     "../docs/examples/mill-turn-job.trace",
    "../docs/examples/planes-helix.trace",     "../docs/examples/sample-job.trace",
    "../docs/examples/subroutine-loops.trace", "../docs/examples/turning-job.trace",
    "../docs/examples/turning-passes.trace",   "../docs/examples/wire-edm-job.trace",
    "golden/fanuc-sample/job.trace",           "golden/solidcam-fanuc/toolpath.trace"};

// The path of machine `machine`'s post or PRP (`extension` "gpp" or "prp").
inline std::string shipped_file(const std::string& machine, const std::string& extension) {
  return "../machines/" + machine + "/" + machine + "." + extension;
}

// An engine's options for that machine's post and PRP.
inline postproc::EngineOptions shipped_post(const std::string& machine) {
  postproc::EngineOptions options;
  options.post = shipped_file(machine, "gpp");
  options.prp = shipped_file(machine, "prp");
  return options;
}

}  // namespace engine_test
