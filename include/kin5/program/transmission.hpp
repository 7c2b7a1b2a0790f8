/// @file program/transmission.hpp
/// The bytes a file transfer adds around a program, which every reader skips the same way:
/// a UTF-8 byte-order mark at offset 0 (editors on Windows write it), and one end-of-transmission
/// byte ETX (0x03) after the program's end (Heidenhain and Fanuc serial transfers end with it;
/// files saved from such a transfer keep it). Only blanks and line ends may follow the ETX.
///
/// A byte-order mark anywhere else is an error at its place: it is no part of any NC word, and
/// a writer that kept it as text would put it at offset 0 of its output, where it would vanish.
/// An ETX before the program has ended is an error at its place: the transfer ended the program
/// early. An ETX with anything but blanks after it is an error at its place too, wherever it
/// stands (in a word or in a comment): no writer could put it back where it was.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <tuple>
#include <utility>

#include "block.hpp"
#include "text.hpp"

namespace kin5::program {

/// A program's text without its transmission bytes, and where its ETX was (line 0: none).
struct transmitted_text {
  std::string_view body;
  std::size_t etx_line = 0, etx_column = 0;  ///< 1-based
};

/// Line and column (1-based) of byte `offset` of `text`, counting CR, LF and CR LF as line ends.
constexpr std::pair<std::size_t, std::size_t> line_and_column(std::string_view text, std::size_t offset) {
  std::size_t line = 1, start = 0;
  for (std::size_t i = 0; i < offset; ++i) {
    if (text[i] != '\n' && text[i] != '\r') continue;
    if (text[i] == '\r' && i + 1 < offset && text[i + 1] == '\n') ++i;
    ++line;
    start = i + 1;
  }
  return {line, offset - start + 1};
}

/// `text` without a byte-order mark at offset 0 and without a final ETX and the blanks and line
/// ends after it.
constexpr transmitted_text strip_transmission(std::string_view text) {
  transmitted_text out;
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
  std::size_t end = text.size();
  while (end > 0 && (is_space(text[end - 1]) || text[end - 1] == '\n' || text[end - 1] == '\r')) --end;
  if (end == 0 || text[end - 1] != '\x03') {
    out.body = text;
    return out;
  }
  out.body = text.substr(0, end - 1);
  std::tie(out.etx_line, out.etx_column) = line_and_column(text, end - 1);
  return out;
}

/// Runs `read(body, on_block')` on `text` without its transmission bytes; `on_block'` passes each
/// block on and notes whether one ended the program. An ETX with no program end before it is an
/// error at the ETX.
template <class Read>
void read_transmitted(std::string_view text, const std::string& file_path, read_result& diagnostics,
                      const block_sink& on_block, Read&& read) {
  const transmitted_text t = strip_transmission(text);
  if (const std::size_t bom = t.body.find("\xEF\xBB\xBF"); bom != std::string_view::npos) {
    const auto [line, column] = line_and_column(t.body, bom);
    diagnostics.add_error({{file_name(file_path), line, column},
                                  "byte-order mark inside the program (one is allowed only at the start of the file)"});
    return;
  }
  if (const std::size_t etx = t.body.find('\x03'); etx != std::string_view::npos) {
    const auto [line, column] = line_and_column(t.body, etx);
    diagnostics.add_error({{file_name(file_path), line, column},
                                  "end-of-transmission byte 0x03 inside the program (one is allowed only after its end)"});
    return;
  }
  if (t.etx_line == 0) {
    read(t.body, on_block);
    return;
  }
  bool ended = false;
  read(t.body, block_sink([&](block&& b) {
         ended = ended || b.program_end.has_value();
         on_block(std::move(b));
       }));
  if (!ended)
    diagnostics.add_error({{file_name(file_path), t.etx_line, t.etx_column},
                                  "end-of-transmission byte 0x03 before the end of the program"});
}

}  // namespace kin5::program
