#include "kinematics/io/json.h"

#include <charconv>
#include <cstdint>
#include <optional>

namespace linkwright::kinematics::io {
namespace {

class Parser {
public:
  explicit Parser(std::string_view text) : m_text(text) {}

  Result<JsonValue> document() {
    JsonValue value;
    skipSpace();
    if (!parseValue(value, 0)) return *m_error;
    skipSpace();
    if (m_pos != m_text.size()) return fail("unexpected text after the document");
    return value;
  }

private:
  Error fail(const std::string& what) {
    int line = 1, column = 1;
    for (std::size_t i = 0; i < m_pos && i < m_text.size(); ++i) {
      if (m_text[i] == '\n') { ++line; column = 1; }
      else ++column;
    }
    m_error = Error{ErrorCode::InvalidValue, "json",
                    "line " + std::to_string(line) + ", column " + std::to_string(column) + ": " + what};
    return *m_error;
  }

  bool error(const std::string& what) {
    fail(what);
    return false;
  }

  bool atEnd() const { return m_pos >= m_text.size(); }
  char peek() const { return atEnd() ? '\0' : m_text[m_pos]; }

  void skipSpace() {
    while (!atEnd() && (peek() == ' ' || peek() == '\t' || peek() == '\n' || peek() == '\r')) ++m_pos;
  }

  bool literal(std::string_view word) {
    if (m_text.substr(m_pos, word.size()) != word) return false;
    m_pos += word.size();
    return true;
  }

  bool parseValue(JsonValue& v, int depth) {
    if (depth > kMaxJsonDepth) return error("nesting deeper than " + std::to_string(kMaxJsonDepth));
    switch (peek()) {
    case '{': return parseObject(v, depth);
    case '[': return parseArray(v, depth);
    case '"': v.type = JsonValue::Type::String; return parseString(v.string);
    case 't': if (literal("true")) { v.type = JsonValue::Type::Bool; v.boolean = true; return true; } break;
    case 'f': if (literal("false")) { v.type = JsonValue::Type::Bool; return true; } break;
    case 'n': if (literal("null")) { v.type = JsonValue::Type::Null; return true; } break;
    default:
      if (peek() == '-' || (peek() >= '0' && peek() <= '9')) return parseNumber(v);
    }
    return error(atEnd() ? "unexpected end of the document" : "expected a value");
  }

  bool parseNumber(JsonValue& v) {
    const std::size_t start = m_pos;
    if (peek() == '-') ++m_pos;
    auto digits = [&] { std::size_t n = 0; while (!atEnd() && peek() >= '0' && peek() <= '9') { ++m_pos; ++n; } return n; };
    if (peek() == '0') ++m_pos;
    else if (digits() == 0) return error("expected a digit");
    if (peek() == '.') { ++m_pos; if (digits() == 0) return error("expected a digit after '.'"); }
    if (peek() == 'e' || peek() == 'E') {
      ++m_pos;
      if (peek() == '+' || peek() == '-') ++m_pos;
      if (digits() == 0) return error("expected an exponent");
    }
    const char* first = m_text.data() + start;
    const auto [ptr, ec] = std::from_chars(first, m_text.data() + m_pos, v.number);
    if (ec != std::errc{} || ptr != m_text.data() + m_pos) {
      m_pos = start;
      return error("number out of range");
    }
    v.type = JsonValue::Type::Number;
    return true;
  }

  static void appendUtf8(std::string& out, std::uint32_t cp) {
    if (cp < 0x80) out += static_cast<char>(cp);
    else if (cp < 0x800) { out += static_cast<char>(0xC0 | (cp >> 6)); out += static_cast<char>(0x80 | (cp & 0x3F)); }
    else if (cp < 0x10000) {
      out += static_cast<char>(0xE0 | (cp >> 12)); out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (cp & 0x3F));
    } else {
      out += static_cast<char>(0xF0 | (cp >> 18)); out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
      out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F)); out += static_cast<char>(0x80 | (cp & 0x3F));
    }
  }

  bool hex4(std::uint32_t& cp) {
    cp = 0;
    for (int i = 0; i < 4; ++i, ++m_pos) {
      const char c = peek();
      cp <<= 4;
      if (c >= '0' && c <= '9') cp |= static_cast<std::uint32_t>(c - '0');
      else if (c >= 'a' && c <= 'f') cp |= static_cast<std::uint32_t>(c - 'a' + 10);
      else if (c >= 'A' && c <= 'F') cp |= static_cast<std::uint32_t>(c - 'A' + 10);
      else return error("expected four hex digits after \\u");
    }
    return true;
  }

  bool parseEscape(std::string& out) {
    const char c = peek();
    ++m_pos;
    switch (c) {
    case '"': out += '"'; return true;
    case '\\': out += '\\'; return true;
    case '/': out += '/'; return true;
    case 'b': out += '\b'; return true;
    case 'f': out += '\f'; return true;
    case 'n': out += '\n'; return true;
    case 'r': out += '\r'; return true;
    case 't': out += '\t'; return true;
    case 'u': {
      std::uint32_t cp = 0;
      if (!hex4(cp)) return false;
      if (cp >= 0xD800 && cp < 0xDC00) {  // a surrogate pair encodes one code point
        std::uint32_t low = 0;
        if (!literal("\\u") || !hex4(low) || low < 0xDC00 || low > 0xDFFF) return error("invalid surrogate pair");
        cp = 0x10000 + ((cp - 0xD800) << 10) + (low - 0xDC00);
      }
      appendUtf8(out, cp);
      return true;
    }
    default: --m_pos; return error("invalid escape in string");
    }
  }

  bool parseString(std::string& out) {
    ++m_pos;  // opening quote
    while (true) {
      if (atEnd()) return error("unterminated string");
      const char c = peek();
      if (c == '"') { ++m_pos; return true; }
      if (static_cast<unsigned char>(c) < 0x20) return error("control character in string");
      ++m_pos;
      if (c != '\\') out += c;
      else if (!parseEscape(out)) return false;
    }
  }

  bool parseArray(JsonValue& v, int depth) {
    v.type = JsonValue::Type::Array;
    ++m_pos;
    skipSpace();
    if (peek() == ']') { ++m_pos; return true; }
    while (true) {
      v.array.emplace_back();
      skipSpace();
      if (!parseValue(v.array.back(), depth + 1)) return false;
      skipSpace();
      if (peek() == ',') { ++m_pos; continue; }
      if (peek() == ']') { ++m_pos; return true; }
      return error("expected ',' or ']'");
    }
  }

  bool parseObject(JsonValue& v, int depth) {
    v.type = JsonValue::Type::Object;
    ++m_pos;
    skipSpace();
    if (peek() == '}') { ++m_pos; return true; }
    while (true) {
      skipSpace();
      if (peek() != '"') return error("expected a member name in quotes");
      std::string key;
      if (!parseString(key)) return false;
      skipSpace();
      if (peek() != ':') return error("expected ':'");
      ++m_pos;
      skipSpace();
      JsonValue member;
      if (!parseValue(member, depth + 1)) return false;
      v.object.emplace_back(std::move(key), std::move(member));
      skipSpace();
      if (peek() == ',') { ++m_pos; continue; }
      if (peek() == '}') { ++m_pos; return true; }
      return error("expected ',' or '}'");
    }
  }

  std::string_view m_text;
  std::size_t m_pos = 0;
  std::optional<Error> m_error;
};

} // namespace

const JsonValue* JsonValue::find(std::string_view key) const {
  for (const auto& [name, value] : object)
    if (name == key) return &value;
  return nullptr;
}

Result<JsonValue> parseJson(std::string_view text) { return Parser(text).document(); }

std::string jsonQuote(std::string_view text) {
  std::string out = "\"";
  for (const char c : text) {
    switch (c) {
    case '"': out += "\\\""; break;
    case '\\': out += "\\\\"; break;
    case '\n': out += "\\n"; break;
    case '\r': out += "\\r"; break;
    case '\t': out += "\\t"; break;
    default:
      if (static_cast<unsigned char>(c) < 0x20) {
        const char* hex = "0123456789abcdef";
        out += "\\u00";
        out += hex[(c >> 4) & 0xF];
        out += hex[c & 0xF];
      } else {
        out += c;
      }
    }
  }
  return out + "\"";
}

} // namespace linkwright::kinematics::io
