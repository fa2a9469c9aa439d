// #include expansion and log mapping; see ShaderIncludeResolver.h.
#include "renderer/ShaderIncludeResolver.h"

#include <cctype>
#include <set>
#include <sstream>

namespace relief::renderer {
namespace {

using core::makeError;

std::string folderOf(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
}

// A tiny cursor over one line; hand-written because std::regex is slow and GCC 12 warns
// falsely inside it under -O2 with sanitizers.
class LineCursor {
 public:
  explicit LineCursor(const std::string& line) : m_line(line) {}
  void skipSpaces() {
    while (m_pos < m_line.size() && std::isspace(static_cast<unsigned char>(m_line[m_pos]))) {
      ++m_pos;
    }
  }
  bool take(const std::string& word) {
    if (m_line.compare(m_pos, word.size(), word) != 0)
      return false;
    m_pos += word.size();
    return true;
  }
  // Up to 9 digits (line numbers); false when there are none or too many.
  bool takeNumber(int& value) {
    std::size_t end = m_pos;
    while (end < m_line.size() && std::isdigit(static_cast<unsigned char>(m_line[end])))
      ++end;
    if (end == m_pos || end - m_pos > 9)
      return false;
    value = std::stoi(m_line.substr(m_pos, end - m_pos));
    m_pos = end;
    return true;
  }
  // Reads up to (not including) `close`; false if it never comes.
  bool takeUntil(char close, std::string& text) {
    const std::size_t end = m_line.find(close, m_pos);
    if (end == std::string::npos)
      return false;
    text = m_line.substr(m_pos, end - m_pos);
    m_pos = end + 1;
    return true;
  }
  std::size_t position() const { return m_pos; }
  std::string rest() const { return m_line.substr(m_pos); }
  bool atEndOrComment() {
    skipSpaces();
    return m_pos == m_line.size() || m_line.compare(m_pos, 2, "//") == 0;
  }

 private:
  const std::string& m_line;
  std::size_t m_pos = 0;
};

// `#include "path"` or `#include <path>`, optionally followed by a // comment.
std::optional<std::string> includeTarget(const std::string& line) {
  LineCursor cursor(line);
  cursor.skipSpaces();
  if (!cursor.take("#"))
    return std::nullopt;
  cursor.skipSpaces();
  if (!cursor.take("include"))
    return std::nullopt;
  cursor.skipSpaces();
  std::string target;
  if (cursor.take("\"")) {
    if (!cursor.takeUntil('"', target))
      return std::nullopt;
  } else if (cursor.take("<")) {
    if (!cursor.takeUntil('>', target))
      return std::nullopt;
  } else {
    return std::nullopt;
  }
  if (target.empty() || !cursor.atEndOrComment())
    return std::nullopt;
  return target;
}

// The line number a driver's log line refers to, with the text before and after it:
//   Mesa:        "0:12(5): error: ..."
//   NVIDIA:      "0(12) : error C0000: ..."
//   AMD / Intel: "ERROR: 0:12: ..."
struct LogLocation {
  std::string prefix;
  int line = 0;
  std::string message;
};

std::optional<LogLocation> parseLogLocation(const std::string& text) {
  LineCursor cursor(text);
  cursor.skipSpaces();
  LogLocation location;
  for (const char* severity : {"ERROR:", "WARNING:"}) {
    if (cursor.take(severity)) {
      cursor.skipSpaces();
      break;
    }
  }
  location.prefix = text.substr(0, cursor.position());
  if (!cursor.take("0"))
    return std::nullopt;
  if (cursor.take(":")) {
    if (!cursor.takeNumber(location.line))
      return std::nullopt;
    int column = 0;
    if (cursor.take("(")) {  // Mesa's column
      if (!cursor.takeNumber(column) || !cursor.take(")"))
        return std::nullopt;
    }
    if (!cursor.take(":"))
      return std::nullopt;
  } else if (cursor.take("(")) {
    if (!cursor.takeNumber(location.line) || !cursor.take(")"))
      return std::nullopt;
    cursor.skipSpaces();
    if (!cursor.take(":"))
      return std::nullopt;
  } else {
    return std::nullopt;
  }
  cursor.skipSpaces();
  location.message = cursor.rest();
  return location;
}

// Joins and normalises "a/b/../c" so that the include-once set sees one name per file.
std::string joinPath(const std::string& folder, const std::string& relative) {
  std::vector<std::string> parts;
  std::stringstream stream(relative.front() == '/' ? relative.substr(1) : folder + relative);
  std::string part;
  while (std::getline(stream, part, '/')) {
    if (part.empty() || part == ".")
      continue;
    if (part == ".." && !parts.empty()) {
      parts.pop_back();
    } else {
      parts.push_back(part);
    }
  }
  std::string joined;
  for (const std::string& p : parts)
    joined += (joined.empty() ? "" : "/") + p;
  return joined;
}

class Expander {
 public:
  explicit Expander(const ShaderSourceLoader& loader) : m_loader(loader) {}

  core::Status expand(const std::string& path, const SourceLocation& includedFrom) {
    if (m_included.count(path))
      return {};
    for (const std::string& open : m_stack) {
      if (open == path) {
        return makeError(includedFrom.file + ":" + std::to_string(includedFrom.line) +
                         ": include cycle through " + path);
      }
    }
    const std::optional<std::string> text = m_loader(path);
    if (!text) {
      if (includedFrom.file.empty())
        return makeError(path + ": shader source not found");
      return makeError(includedFrom.file + ":" + std::to_string(includedFrom.line) +
                       ": cannot include \"" + path + "\": file not found");
    }
    m_stack.push_back(path);
    std::istringstream lines(*text);
    std::string line;
    int lineNumber = 0;
    while (std::getline(lines, line)) {
      ++lineNumber;
      if (!line.empty() && line.back() == '\r')
        line.pop_back();
      if (const std::optional<std::string> included = includeTarget(line)) {
        const std::string target = joinPath(folderOf(path), *included);
        core::Status status = expand(target, SourceLocation{path, lineNumber});
        if (!status)
          return status;
        continue;
      }
      append(line, SourceLocation{path, lineNumber});
    }
    m_stack.pop_back();
    m_included.insert(path);
    return {};
  }

  void append(const std::string& line, SourceLocation origin) {
    m_result.source += line;
    m_result.source += '\n';
    m_result.lineOrigins.push_back(std::move(origin));
  }

  ResolvedShader take() { return std::move(m_result); }

 private:
  const ShaderSourceLoader& m_loader;
  std::set<std::string> m_included;
  std::vector<std::string> m_stack;
  ResolvedShader m_result;
};

}  // namespace

core::Result<ResolvedShader> resolveShaderIncludes(const std::string& path,
                                                   const ShaderSourceLoader& loader,
                                                   const std::string& prelude) {
  Expander expander(loader);
  std::istringstream preludeLines(prelude);
  std::string line;
  int lineNumber = 0;
  while (std::getline(preludeLines, line)) {
    expander.append(line, SourceLocation{"<prelude>", ++lineNumber});
  }
  core::Status status = expander.expand(path, SourceLocation{});
  if (!status)
    return makeError(status.error());
  return expander.take();
}

std::string mapShaderLog(const std::string& log, const std::vector<SourceLocation>& lineOrigins) {
  // Source string 0 is the whole program text, so the first number is the string index and
  // the second the line in it.
  std::istringstream lines(log);
  std::string line;
  std::string mapped;
  while (std::getline(lines, line)) {
    const std::optional<LogLocation> location = parseLogLocation(line);
    if (location && location->line >= 1 && std::size_t(location->line) <= lineOrigins.size()) {
      const SourceLocation& origin = lineOrigins[std::size_t(location->line) - 1];
      line = location->prefix + origin.file + ":" + std::to_string(origin.line) + ": " +
             location->message;
    }
    mapped += line;
    mapped += '\n';
  }
  return mapped;
}

}  // namespace relief::renderer
