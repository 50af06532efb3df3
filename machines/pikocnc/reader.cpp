#include "machines/pikocnc/reader.hpp"

#include <fstream>

#include "machines/pikocnc/interpreter.hpp"

namespace pikocnc {

PikoReader::PikoReader(std::istream& in, std::string file_name, Options options)
    : interpreter_(std::make_unique<Interpreter>(in, std::move(file_name), std::move(options))) {}

PikoReader::~PikoReader() = default;

std::unique_ptr<PikoReader> PikoReader::open(const std::string& path, Options options) {
  auto file = std::make_unique<std::ifstream>(path, std::ios::binary);
  if (!*file) throw toolpath::InputError({path, 0, 0}, "cannot open file");
  auto reader = std::make_unique<PikoReader>(*file, path, std::move(options));
  reader->owned_ = std::move(file);
  return reader;
}

bool PikoReader::next(toolpath::Command& out) {
  if (!interpreter_->run()) return false;
  return interpreter_->emitter().pop(out, line_);
}

const Diagnostics& PikoReader::diagnostics() const { return interpreter_->diagnostics(); }
const std::string& PikoReader::file_name() const { return interpreter_->file_name(); }

}  // namespace pikocnc
