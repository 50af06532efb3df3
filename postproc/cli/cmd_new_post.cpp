// `postproc new-post --template NAME`: writes a documented starter post and its machine file, one
// of the posts we ship and test for a common controller, as the base of a user's own post.
#include <fmt/format.h>

#include <cctype>
#include <filesystem>
#include <ostream>
#include <string>

#include "machines/templates/post_templates.hpp"
#include "postproc/cli/cli.hpp"
#include "postproc/cli/cli_support.hpp"
#include "toolpath/error.hpp"

namespace postproc::cli {
namespace {

namespace fs = std::filesystem;

std::string template_list() {
  std::string list;
  for (const auto& t : machines::post_templates()) list += fmt::format("  {:<13}{}\n", t.name, t.summary);
  return list;
}

// A post name becomes two file names and the PRP's post_processor value: keep it to one word.
bool valid_post_name(const std::string& name) {
  if (name.empty() || name.size() > 64) return false;
  for (char c : name)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-')) return false;
  return true;
}

int run_new_post(const Arguments& args, std::ostream& out, std::ostream& err) {
  if (args.has("--list")) {
    out << template_list();
    return kOk;
  }
  if (!args.positional().empty()) throw UsageError{"unexpected argument " + args.positional()[0]};
  const std::string wanted = args.value("--template");
  if (wanted.empty()) throw UsageError{"--template NAME is required; the templates are:\n" + template_list()};
  const machines::PostTemplate* t = machines::find_post_template(wanted);
  if (!t) throw UsageError{fmt::format("no template '{}'; the templates are:\n{}", wanted, template_list())};
  const std::string name = args.value("--name", t->name);
  if (!valid_post_name(name)) throw UsageError{"--name takes letters, digits, '_' and '-' (it names the files and the post)"};
  const fs::path dir = args.value("--output", ".");
  const fs::path gpp = dir / (name + ".gpp"), prp = dir / (name + ".prp");
  if (!args.has("--force"))
    for (const auto& p : {gpp, prp})
      if (fs::exists(p)) throw toolpath::InputError({p.string(), 0, 0}, "already exists; --force replaces it");
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw toolpath::InputError({dir.string(), 0, 0}, "cannot create the folder: " + ec.message());
  write_file_replacing(gpp.string(), t->gpp);
  write_file_replacing(prp.string(), machines::renamed_machine_file(*t, name));
  out << fmt::format(
      "wrote {} and {} ({} template)\n"
      "next: postproc check {} --prp {}\n"
      "      postproc run --post {} --prp {} docs/examples/{}.trace -o OUT_DIR\n"
      "      (docs/examples/{}.trace of the postproc sources is the job its tests post)\n",
      gpp.string(), prp.string(), t->name, gpp.string(), prp.string(), gpp.string(), prp.string(), t->sample_job,
      t->sample_job);
  (void)err;
  return kOk;
}

}  // namespace

Subcommand new_post_command() {
  return {
      "new-post",
      "postproc new-post --template NAME [--name POST] [-o DIR] [--force] | --list",
      "Write a documented starter post and machine file for a common controller.",
      {
          {"--template", "-t", true, "the machine: fanuc, linuxcnc, grbl, sinumerik, fanuc-lathe, mill-turn, wire-edm (--list describes them)"},
          {"--name", "", true, "the new post's name: files POST.gpp and POST.prp (default: the template's name)"},
          {"--output", "-o", true, "the folder to write them in (default: the current folder; created when missing)"},
          {"--force", "", false, "replace files that already exist"},
          {"--list", "", false, "list the templates and exit"},
      },
      run_new_post,
  };
}

}  // namespace postproc::cli
