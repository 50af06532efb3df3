// Starter posts for `postproc new-post`: each one a post we ship and test (machines/NAME/), with
// its machine file, compiled into the tool so that a user needs nothing but the binary.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace machines {

struct PostTemplate {
  std::string_view name;     // "fanuc": the --template value and the folder under machines/
  std::string_view sample_job;  // "sample-job": docs/examples/<sample_job>.trace posts through it
  std::string_view summary;  // the controllers it is written for
  std::string_view gpp;      // the post
  std::string_view prp;      // its machine file
};

// In the order `new-post --list` prints them.
const std::vector<PostTemplate>& post_templates();
const PostTemplate* find_post_template(std::string_view name);

// The machine file renamed for a post called `post_name`: its post_processor and doc_processor
// lines name the new post (SolidCAM finds a post by that name).
std::string renamed_machine_file(const PostTemplate& t, std::string_view post_name);

}  // namespace machines
