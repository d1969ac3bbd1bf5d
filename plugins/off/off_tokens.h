// Splits OFF text into whitespace-separated tokens, dropping '#' comments
// (to the end of their line, wherever they start) and remembering each
// token's line. OFF is token-based -- records may wrap over lines -- but a few
// decisions (is there an edge count? how many colour numbers follow a face?)
// depend on what is left on a line, hence peekSameLine().
#pragma once

#include <cstdint>
#include <string_view>

namespace prism_plugins {

class OffTokens {
 public:
  explicit OffTokens(std::string_view text) : m_text(text) {}

  // The next token (empty at the end of the text).
  std::string_view next() {
    advance();
    std::string_view t = m_peeked;
    m_line = m_peeked_line;
    m_has_peek = false;
    return t;
  }
  // Line of the token next() returned last (1-based).
  std::uint64_t line() const { return m_line; }
  // True when another token follows on the line of the last one.
  bool peekSameLine() {
    advance();
    return !m_peeked.empty() && m_peeked_line == m_line;
  }
  bool atEnd() {
    advance();
    return m_peeked.empty();
  }
  // Bytes not yet consumed: an upper bound on what is left to read.
  std::uint64_t remainingBytes() const { return m_text.size() - m_pos; }

 private:
  void advance() {
    if (m_has_peek) return;
    m_has_peek = true;
    for (;;) {
      while (m_pos < m_text.size()) {
        char c = m_text[m_pos];
        if (c == '\n') {
          ++m_cursor_line;
        } else if (c == '\r') {
          // "\r\n" counts once; a lone '\r' ends a line too.
          if (m_pos + 1 >= m_text.size() || m_text[m_pos + 1] != '\n') ++m_cursor_line;
        } else if (!(c == ' ' || c == '\t' || c == '\f' || c == '\v')) {
          break;
        }
        ++m_pos;
      }
      if (m_pos < m_text.size() && m_text[m_pos] == '#') {
        while (m_pos < m_text.size() && m_text[m_pos] != '\n' && m_text[m_pos] != '\r') ++m_pos;
        continue;
      }
      break;
    }
    std::size_t start = m_pos;
    while (m_pos < m_text.size()) {
      char c = m_text[m_pos];
      if (c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v' || c == '#') break;
      ++m_pos;
    }
    m_peeked = m_text.substr(start, m_pos - start);
    m_peeked_line = m_cursor_line;
  }

  std::string_view m_text;
  std::size_t m_pos = 0;
  std::uint64_t m_cursor_line = 1;
  std::uint64_t m_line = 1;
  std::string_view m_peeked;
  std::uint64_t m_peeked_line = 1;
  bool m_has_peek = false;
};

}  // namespace prism_plugins
