// Test helper shared by the reader suites: damage a good input at random places.
#pragma once

#include <random>
#include <string>
#include <string_view>

namespace test_support {

// `edits` random edits of `text`: a byte replaced, a byte inserted (both from `alphabet`), up to
// eight bytes erased, or the text cut short.
inline void random_edits(std::string& text, std::mt19937& rng, std::string_view alphabet, int edits) {
  for (int e = 0; e < edits; ++e) {
    const std::size_t at = rng() % (text.size() + 1);
    switch (rng() % 4) {
      case 0: if (at < text.size()) text[at] = alphabet[rng() % alphabet.size()]; break;
      case 1: text.insert(at, 1, alphabet[rng() % alphabet.size()]); break;
      case 2: if (at < text.size()) text.erase(at, 1 + rng() % 8); break;
      case 3: text.resize(at); break;
    }
  }
}

}  // namespace test_support
