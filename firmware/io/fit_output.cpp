#include "io/fit_output.hpp"

#include <cmath>
#include <cstdio>

// Text is built with += throughout: GCC 12 at -O3 reports a false -Wrestrict
// on `"literal" + std::string` (GCC bug 105329).

namespace kerf::io {

double resolution(Span<const Vec2<double>> pts) {
  double m = 0.0;
  for (const Vec2<double>& p : pts) m = std::fmax(m, std::fmax(std::fabs(p.x), std::fabs(p.y)));
  return m * 1e-12;
}

int coordinate_digits(Span<const fit::Piece<double>> pieces, double tol) {
  double big = 0.0;
  for (const fit::Piece<double>& p : pieces) {
    const Segment<double>& s = p.segment;
    big = std::fmax(big, std::fmax(std::fabs(s.start.x), std::fabs(s.start.y)));
    big = std::fmax(big, std::fmax(std::fabs(s.end.x), std::fabs(s.end.y)));
    if (s.is_arc()) big = std::fmax(big, std::fmax(std::fabs(s.centre.x), std::fabs(s.centre.y)));
  }
  if (!(big > 0.0) || !(tol > 0.0) || !std::isfinite(big)) return kDigits;
  // d digits print big to half a unit of 10^(floor(log10 big) + 1 - d).
  const double need = std::floor(std::log10(big)) + 1.0 - std::log10(2e-3 * tol);
  return need <= kDigits ? kDigits : need >= 17.0 ? 17 : static_cast<int>(std::ceil(need));
}

std::string format_number(double v, double zero_below, int digits) {
  if (std::fabs(v) < zero_below || v == 0.0) v = 0.0;  // also prints -0 as 0
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

namespace {

void add_point(std::string& out, Vec2<double> p, double z, int digits) {
  out += '(';
  out += format_number(p.x, z, digits);
  out += ',';
  out += format_number(p.y, z, digits);
  out += ')';
}

// JSON has no NaN or infinity.
void add_json_number(std::string& out, double v, double z, int digits = kDigits) {
  out += std::isfinite(v) ? format_number(v, z, digits) : std::string("null");
}

void add_json_point(std::string& out, Vec2<double> p, double z, int digits) {
  out += '[';
  add_json_number(out, p.x, z, digits);
  out += ", ";
  add_json_number(out, p.y, z, digits);
  out += ']';
}

void add_json_string(std::string& out, const char* s) {
  out += '"';
  for (; *s != '\0'; ++s) {
    const auto c = static_cast<unsigned char>(*s);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += static_cast<char>(c);
    } else if (c < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(c));
      out += buf;
    } else {
      out += static_cast<char>(c);
    }
  }
  out += '"';
}

// `"key": ` after the indentation.
void add_key(std::string& out, const char* key) {
  add_json_string(out, key);
  out += ": ";
}

}  // namespace

std::string format_esgi(const FitReport& r) {
  const double z = r.zero_below;
  std::string out;
  out += "# kerf fit: criterion ";
  out += r.criterion;
  out += ", method ";
  out += r.method;
  out += "\n# tol ";
  out += format_number(r.fit.tol);  // as given, however small
  out += "\n# max error ";
  out += format_number(r.fit.max_error, z);
  if (r.biarcs) {
    out += "\n# Number of biarcs is ";
    out += std::to_string(r.fit.pieces / 2);
  }
  out += "\nNumber of arcs is Narc = ";
  out += std::to_string(r.fit.pieces);
  out += '\n';
  for (std::uint32_t k = 0; k < r.fit.pieces; ++k) {
    const Segment<double>& s = r.pieces[k].segment;
    if (r.biarcs && k % 2 == 0) {
      out += "# biarc ";
      out += std::to_string(k / 2 + 1);
      out += ": points ";
      out += std::to_string(r.pieces[k].first);
      out += "..";
      out += std::to_string(r.pieces[k].last);
      out += '\n';
    }
    out += esgi_piece_line(s, z, r.digits);
  }
  return out;
}

std::string esgi_piece_line(const Segment<double>& s, double z, int digits) {
  std::string out = s.is_arc() ? "A " : "L ";
  add_point(out, s.start, z, digits);
  out += ' ';
  add_point(out, s.end, z, digits);
  if (s.is_arc()) {
    out += ' ';
    add_point(out, s.centre, z, digits);
    out += s.dir > 0 ? " 1" : " -1";
  }
  out += '\n';
  return out;
}

std::string format_json(const FitReport& r) {
  const double z = r.zero_below;
  std::string out = "{\n  ";
  add_key(out, "criterion");
  add_json_string(out, r.criterion);
  out += ",\n  ";
  add_key(out, "method");
  add_json_string(out, r.method);
  out += ",\n  ";
  add_key(out, "tol");
  add_json_number(out, r.fit.tol, 0.0);  // as given, however small
  out += ",\n  ";
  add_key(out, "max_error");
  add_json_number(out, r.fit.max_error, z);
  out += ",\n  ";
  if (r.biarcs) {
    add_key(out, "biarcs");
    out += std::to_string(r.fit.pieces / 2);
    out += ",\n  ";
  }
  add_key(out, "pieces");
  out += '[';
  for (std::uint32_t k = 0; k < r.fit.pieces; ++k) {
    const fit::Piece<double>& p = r.pieces[k];
    const Segment<double>& s = p.segment;
    out += k == 0 ? "\n    {" : ",\n    {";
    add_key(out, "type");
    add_json_string(out, s.is_arc() ? "arc" : "line");
    out += ", ";
    add_key(out, "first");
    out += std::to_string(p.first);
    out += ", ";
    add_key(out, "last");
    out += std::to_string(p.last);
    out += ", ";
    if (r.biarcs) {
      add_key(out, "biarc");
      out += std::to_string(k / 2);
      out += ", ";
      add_key(out, "part");
      out += k % 2 == 0 ? "1" : "2";
      out += ", ";
    }
    add_key(out, "start");
    add_json_point(out, s.start, z, r.digits);
    out += ", ";
    add_key(out, "end");
    add_json_point(out, s.end, z, r.digits);
    if (s.is_arc()) {
      out += ", ";
      add_key(out, "centre");
      add_json_point(out, s.centre, z, r.digits);
      out += ", ";
      add_key(out, "dir");
      out += s.dir > 0 ? "1" : "-1";
    }
    out += ", ";
    add_key(out, "error");
    add_json_number(out, p.error, z);
    out += '}';
  }
  out += r.fit.pieces == 0 ? "]\n}\n" : "\n  ]\n}\n";
  return out;
}

}  // namespace kerf::io
