// prp::load_file reads PRP, .MAC and VMID files in chunks and stops past 64 MiB, also on a device
// that reports no size (/dev/zero); the files we ship still load (docs/reliability.md).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "prp/prp.hpp"
#include "toolpath/error.hpp"

namespace fs = std::filesystem;

namespace {

std::string load_result(const std::string& path) {
  try {
    prp::load_file(path, prp::Units::Metric);
    return "loaded";
  } catch (const std::exception& e) {
    return e.what();
  }
}

TEST(FileSize, LargeFilesAndDevicesAreAnError) {
  const fs::path dir = fs::temp_directory_path() / ("prp_file_size_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  // Sparse files of 65 MiB (no disk space taken): one per machine-file kind the loader takes.
  const auto sparse = [&](const char* name) {
    const fs::path p = dir / name;
    std::ofstream(p, std::ios::binary) << "@pre_processor\n";
    fs::resize_file(p, std::uintmax_t{65} << 20);
    return p.string();
  };
  const std::string prp = sparse("big.prp"), mac = sparse("BIG.MAC"), vmid = sparse("big.vmid");
  const struct {
    const char* name;
    std::string path;
    std::string expected;
  } cases[] = {
      {"Device", "/dev/zero", "/dev/zero: larger than 64 MiB: not a PRP file?"},
      {"Prp", prp, prp + ": larger than 64 MiB: not a PRP file?"},
      {"Mac", mac, mac + ": larger than 64 MiB: not a PRP file?"},
      {"Vmid", vmid, vmid + ": larger than 64 MiB: not a PRP file?"},
      {"Missing", (dir / "none.prp").string(), (dir / "none.prp").string() + ": cannot open the PRP file"},
      {"ShippedPrp", "prp/data/fanuc.prp", "loaded"},
      {"ShippedMac", "prp/data/fanuc-old.MAC", "loaded"},
      {"ShippedVmid", "prp/data/mill-4x.vmid", "loaded"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    EXPECT_EQ(load_result(c.path), c.expected);
  }
  std::error_code ignored;
  fs::remove_all(dir, ignored);
}

}  // namespace
