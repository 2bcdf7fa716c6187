// Helpers shared by the fuzz harnesses (fuzz/README in the top-level README, "Fuzzing and
// sanitizers"): a scratch folder per process, files written from the input, input splitting.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace impact3d_fuzz {

// A folder of this process under $TMPDIR (or /tmp), made on first use and removed at exit.
const std::filesystem::path& scratch_dir();

// Writes bytes to path (replacing it); aborts when the file cannot be written (a broken
// harness, not a finding).
void write_file(const std::filesystem::path& path, std::string_view bytes);

// Cuts the input at every occurrence of sep (at most max_parts parts; the last part keeps the
// rest).
std::vector<std::string_view> split_parts(std::string_view in, std::string_view sep, std::size_t max_parts);

// The input as text.
inline std::string_view as_text(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

// Splits a binary input into a root file and a member file: the first 4 bytes (little endian)
// give the root's length (taken modulo what follows); the rest after the root is the member.
void split_root_member(std::string_view in, std::string_view& root, std::string_view& member);

// The header-count mutation of the plot-database targets (fuzz/libfuzzer_main.cpp, with
// libFuzzer's own mutations): in an input laid out as split_root_member reads it, writes one of
// the extreme values 0, -1, 2^31 - 1, 2^31, 2^63 - 1 (as a 4- or 8-byte integer: the word size
// the VERSION word shows, else chosen by seed) into one count word of the root file's control
// words or EXTRA words.  Returns false (input unchanged) when the input has no control words.
bool write_extreme_header_count(std::uint8_t* data, std::size_t size, unsigned seed);

}  // namespace impact3d_fuzz
