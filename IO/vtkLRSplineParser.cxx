#include "vtkLRSplineParser.h"

#include "vtkLRSplineBezierVolume.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <sstream>

namespace
{
// Internal: parse errors unwind to Parse() which turns them into a message.
struct ParseError
{
  int Line;
  std::string Message;
};

struct Token
{
  enum Kind
  {
    End,
    Word,
    Punct,
    Comment
  };
  Kind Type = End;
  std::string Text;
  int Line = 0;
};

bool IsPunct(char c)
{
  return c == ':' || c == '[' || c == ']' || c == '(' || c == ')' || c == ',' || c == '{' ||
    c == '}';
}

class Tokenizer
{
public:
  Tokenizer(const std::string& text, bool comments)
    : P(text.data())
    , E(text.data() + text.size())
    , Comments(comments)
  {
  }

  const Token& Peek()
  {
    if (!this->HavePeek)
    {
      this->Peeked = this->Read();
      this->HavePeek = true;
    }
    return this->Peeked;
  }
  Token Next()
  {
    Token t = this->Peek();
    this->HavePeek = false;
    return t;
  }
  /// The last line that had a token (the line to report at the end of the file).
  int Line() const { return this->LastLine; }

private:
  Token Read()
  {
    Token t;
    for (;;)
    {
      while (this->P < this->E && std::isspace(static_cast<unsigned char>(*this->P)))
      {
        if (*this->P == '\n')
        {
          ++this->CurrentLine;
        }
        ++this->P;
      }
      t.Line = this->CurrentLine;
      if (this->P >= this->E)
      {
        t.Type = Token::End;
        t.Line = this->LastLine; // the last line with content
        return t;
      }
      this->LastLine = this->CurrentLine;
      if (this->Comments && *this->P == '#')
      {
        const char* start = ++this->P;
        while (this->P < this->E && *this->P != '\n')
        {
          ++this->P;
        }
        t.Type = Token::Comment;
        t.Text.assign(start, this->P);
        return t;
      }
      if (*this->P == '\0')
      {
        throw ParseError{ this->CurrentLine, "the file contains a NUL byte (not a text file?)" };
      }
      if (IsPunct(*this->P))
      {
        t.Type = Token::Punct;
        t.Text.assign(1, *this->P);
        ++this->P;
        return t;
      }
      const char* start = this->P;
      while (this->P < this->E && !std::isspace(static_cast<unsigned char>(*this->P)) &&
        !IsPunct(*this->P) && *this->P != '#' && *this->P != '\0')
      {
        ++this->P;
      }
      t.Type = Token::Word;
      t.Text.assign(start, this->P);
      if (t.Text.size() > 64)
      {
        throw ParseError{ t.Line, "a token is too long: \"" + t.Text.substr(0, 40) + "...\"" };
      }
      return t;
    }
  }

  const char* P;
  const char* E;
  bool Comments;
  int CurrentLine = 1;
  int LastLine = 1;
  Token Peeked;
  bool HavePeek = false;
};

std::string Describe(const Token& t)
{
  switch (t.Type)
  {
    case Token::End:
      return "the end of the file";
    case Token::Comment:
      return "the comment \"#" + t.Text.substr(0, 40) + "\"";
    default:
      return "\"" + t.Text + "\"";
  }
}

double ToNumber(const Token& t, const std::string& what)
{
  if (t.Type != Token::Word)
  {
    throw ParseError{ t.Line, "expected a number (" + what + "), found " + Describe(t) };
  }
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(t.Text.c_str(), &end);
  if (end != t.Text.c_str() + t.Text.size() || t.Text.empty())
  {
    throw ParseError{ t.Line, "expected a number (" + what + "), found " + Describe(t) };
  }
  return v; // NaN/inf are reported by Validate() with their line
}

long long ToInteger(const Token& t, const std::string& what, long long lo, long long hi)
{
  if (t.Type != Token::Word)
  {
    throw ParseError{ t.Line, "expected an integer (" + what + "), found " + Describe(t) };
  }
  errno = 0;
  char* end = nullptr;
  const long long v = std::strtoll(t.Text.c_str(), &end, 10);
  if (end != t.Text.c_str() + t.Text.size() || t.Text.empty() || errno == ERANGE)
  {
    throw ParseError{ t.Line, "expected an integer (" + what + "), found " + Describe(t) };
  }
  if (v < lo || v > hi)
  {
    std::ostringstream msg;
    msg << what << " is " << v << ", expected " << lo << " to " << hi;
    throw ParseError{ t.Line, msg.str() };
  }
  return v;
}

//------------------------------------------------------------------------------
// LRSplines text format
class LRReader
{
public:
  LRReader(const std::string& text)
    : Tok(text, true)
  {
  }

  // Next data token: comments are skipped, but a new patch header inside a
  // patch means this one is incomplete.
  Token Data(const std::string& context)
  {
    for (;;)
    {
      Token t = this->Tok.Next();
      if (t.Type == Token::Comment)
      {
        if (t.Text.find("LRSPLINE") != std::string::npos)
        {
          throw ParseError{ t.Line,
            "a new patch header starts while reading " + context + " (the patch is incomplete)" };
        }
        continue;
      }
      if (t.Type == Token::End)
      {
        throw ParseError{ this->Tok.Line(),
          "unexpected end of file while reading " + context + " (the file is truncated)" };
      }
      return t;
    }
  }
  void Expect(const char* punct, const std::string& context)
  {
    Token t = this->Data(context);
    if (t.Text != punct)
    {
      throw ParseError{ t.Line,
        std::string("expected '") + punct + "' in " + context + ", found " + Describe(t) };
    }
  }
  double Number(const std::string& context) { return ToNumber(this->Data(context), context); }
  long long Integer(const std::string& context, long long lo, long long hi)
  {
    return ToInteger(this->Data(context), context, lo, hi);
  }

  void Parse(std::vector<vtkLRSplinePatch>& patches)
  {
    for (;;)
    {
      Token t = this->Tok.Next();
      if (t.Type == Token::End)
      {
        break;
      }
      if (t.Type == Token::Comment)
      {
        std::string text = t.Text;
        // normalize whitespace
        std::istringstream words(text);
        std::string w1, w2;
        words >> w1 >> w2;
        if (w1 == "LRSPLINE" && w2 == "VOLUME")
        {
          patches.emplace_back();
          patches.back().HeaderLine = t.Line;
          this->ParseVolume(patches.back(), static_cast<int>(patches.size()) - 1);
          continue;
        }
        if (w1 == "LRSPLINE" && w2 == "SURFACE")
        {
          throw ParseError{ t.Line,
            "this is an LR-spline SURFACE (\"# LRSPLINE SURFACE\"); the reader reads volumes "
            "(\"# LRSPLINE VOLUME\")" };
        }
        if (w1 == "LRSPLINE" && w2.empty())
        {
          throw ParseError{ t.Line,
            "\"# LRSPLINE\" without VOLUME is the pre-2013 surface format; the reader reads "
            "volumes (\"# LRSPLINE VOLUME\")" };
        }
        if (w1 == "LRSPLINE")
        {
          throw ParseError{ t.Line,
            "unknown header " + Describe(t) + ", expected \"# LRSPLINE VOLUME\"" };
        }
        if (patches.empty() &&
          (w1.find("LRSPLINE") != std::string::npos || text.find("LRSPLINE") != std::string::npos))
        {
          throw ParseError{ t.Line,
            "unknown header " + Describe(t) + ", expected \"# LRSPLINE VOLUME\"" };
        }
        continue; // an ordinary comment
      }
      if (patches.empty())
      {
        throw ParseError{ t.Line,
          "unknown header: expected \"# LRSPLINE VOLUME\", found " + Describe(t) };
      }
      throw ParseError{ t.Line,
        "unexpected " + Describe(t) + " after the last element of patch " +
          std::to_string(patches.size() - 1) + " (wrong element count in its header?)" };
    }
    if (patches.empty())
    {
      throw ParseError{ this->Tok.Line(),
        "no LR-spline volume found (expected a \"# LRSPLINE VOLUME\" header)" };
    }
  }

private:
  void ParseVolume(vtkLRSplinePatch& patch, int index)
  {
    const std::string ctx = "the header of patch " + std::to_string(index);
    const int maxOrder = vtkLRSplineBezierVolume::MaximumDegree + 1;
    for (int d = 0; d < 3; ++d)
    {
      patch.Order[d] =
        static_cast<int>(this->Integer(ctx + ": order p" + std::to_string(d + 1), 1, maxOrder));
    }
    const long long maxCount = 100000000LL;
    const vtkIdType nb =
      static_cast<vtkIdType>(this->Integer(ctx + ": number of basis functions", 1, maxCount));
    const vtkIdType nl =
      static_cast<vtkIdType>(this->Integer(ctx + ": number of mesh rectangles", 0, maxCount));
    const vtkIdType ne =
      static_cast<vtkIdType>(this->Integer(ctx + ": number of elements", 1, maxCount));
    patch.Dimension = static_cast<int>(this->Integer(ctx + ": dimension", 1, 64));
    patch.Rational = static_cast<int>(this->Integer(ctx + ": rational flag", 0, 1));

    const int kpf = patch.GetKnotsPerFunction();
    const std::size_t cap = 1 << 20; // never trust a count for allocation
    patch.Knots.reserve(std::min<std::size_t>(cap, static_cast<std::size_t>(nb) * kpf));
    for (vtkIdType i = 0; i < nb; ++i)
    {
      const std::string bctx = "basis function " + std::to_string(i) + " of " + std::to_string(nb) +
        " (patch " + std::to_string(index) + ")";
      Token idTok = this->Data(bctx);
      patch.BasisLines.push_back(idTok.Line);
      if (idTok.Text == "[")
      {
        throw ParseError{ idTok.Line,
          "found a mesh rectangle where " + bctx +
            " was expected (wrong basis function count in the header?)" };
      }
      const long long id = ToInteger(idTok, bctx + ": id", 0, maxCount);
      if (id != i)
      {
        throw ParseError{ idTok.Line,
          "basis function ids must count 0, 1, 2, ...: expected " + std::to_string(i) + ", found " +
            std::to_string(id) };
      }
      this->Expect(":", bctx);
      for (int d = 0; d < 3; ++d)
      {
        if (d > 0)
        {
          this->Expect("x", bctx);
        }
        this->Expect("[", bctx);
        const int want = patch.Order[d] + 1;
        int count = 0;
        for (;;)
        {
          Token t = this->Data(bctx);
          if (t.Text == "]")
          {
            break;
          }
          if (count == want)
          {
            throw ParseError{ t.Line,
              bctx + ": knot vector " + "uvw"[d] +
                " has more than order + 1 = " + std::to_string(want) + " values" };
          }
          patch.Knots.push_back(ToNumber(t, bctx + ": knot"));
          ++count;
        }
        if (count != want)
        {
          throw ParseError{ this->Tok.Line(),
            bctx + ": knot vector " + "uvw"[d] + " has " + std::to_string(count) +
              " values, expected order + 1 = " + std::to_string(want) };
        }
      }
      for (int c = 0; c < patch.Dimension; ++c)
      {
        patch.Coefficients.push_back(this->Number(bctx + ": coefficient"));
      }
      this->Expect("(", bctx + " (before gamma)");
      patch.Gamma.push_back(this->Number(bctx + ": gamma"));
      this->Expect(")", bctx + " (after gamma)");
    }
    for (vtkIdType r = 0; r < nl; ++r)
    {
      const std::string rctx = "mesh rectangle " + std::to_string(r) + " of " + std::to_string(nl) +
        " (patch " + std::to_string(index) + ")";
      double lo[3], hi[3];
      int line = 0;
      for (int d = 0; d < 3; ++d)
      {
        if (d > 0)
        {
          this->Expect("x", rctx);
        }
        Token open = this->Data(rctx);
        line = open.Line;
        if (open.Text != "[")
        {
          throw ParseError{ open.Line,
            "expected '[' in " + rctx + ", found " + Describe(open) +
              (open.Type == Token::Word ? (r == 0 ? " (wrong basis function count in the header?)"
                                                  : " (wrong mesh rectangle count in the header?)")
                                        : "") };
        }
        lo[d] = this->Number(rctx);
        this->Expect(",", rctx);
        hi[d] = this->Number(rctx);
        this->Expect("]", rctx);
      }
      this->Expect("(", rctx);
      const int m = static_cast<int>(this->Integer(rctx + ": multiplicity", 1, 64));
      this->Expect(")", rctx);
      int flat = 0;
      for (int d = 0; d < 3; ++d)
      {
        if (!std::isfinite(lo[d]) || !std::isfinite(hi[d]) || hi[d] < lo[d])
        {
          throw ParseError{ line, rctx + ": invalid interval" };
        }
        flat += lo[d] == hi[d] ? 1 : 0;
      }
      if (flat != 1)
      {
        throw ParseError{ line, rctx + ": exactly one direction must be constant (start = stop)" };
      }
      patch.MeshRectangles.insert(
        patch.MeshRectangles.end(), { lo[0], lo[1], lo[2], hi[0], hi[1], hi[2] });
      patch.MeshMultiplicities.push_back(m);
    }
    patch.FileSupportOffsets.push_back(0);
    for (vtkIdType e = 0; e < ne; ++e)
    {
      const std::string ectx = "element " + std::to_string(e) + " of " + std::to_string(ne) +
        " (patch " + std::to_string(index) + ")";
      Token idTok = this->Data(ectx);
      patch.ElementLines.push_back(idTok.Line);
      if (idTok.Text == "[")
      {
        throw ParseError{ idTok.Line,
          "expected an element, found a mesh rectangle (wrong mesh "
          "rectangle count in the header?)" };
      }
      const long long id = ToInteger(idTok, ectx + ": id", 0, maxCount);
      if (id != e)
      {
        throw ParseError{ idTok.Line,
          "element ids must count 0, 1, 2, ...: expected " + std::to_string(e) + ", found " +
            std::to_string(id) };
      }
      this->Expect("[", ectx);
      const Token dimTok = this->Data(ectx);
      if (ToInteger(dimTok, ectx + ": parametric dimension", 0, 1000) != 3)
      {
        throw ParseError{ dimTok.Line, ectx + ": parametric dimension must be 3" };
      }
      this->Expect("]", ectx);
      this->Expect(":", ectx);
      double box[6];
      for (int corner = 0; corner < 2; ++corner)
      {
        if (corner == 1)
        {
          this->Expect("x", ectx);
        }
        this->Expect("(", ectx);
        for (int d = 0; d < 3; ++d)
        {
          if (d > 0)
          {
            this->Expect(",", ectx);
          }
          box[3 * corner + d] = this->Number(ectx + ": corner");
        }
        this->Expect(")", ectx);
      }
      patch.ElementBoxes.insert(patch.ElementBoxes.end(), box, box + 6);
      this->Expect("{", ectx);
      Token t = this->Data(ectx);
      if (t.Text != "}")
      {
        for (;;)
        {
          patch.FileSupport.push_back(
            static_cast<vtkIdType>(ToInteger(t, ectx + ": basis function index", 0, maxCount)));
          t = this->Data(ectx);
          if (t.Text == "}")
          {
            break;
          }
          if (t.Text != ",")
          {
            throw ParseError{ t.Line,
              "expected ',' or '}' in the support list of " + ectx + ", found " + Describe(t) };
          }
          t = this->Data(ectx);
        }
      }
      patch.FileSupportOffsets.push_back(static_cast<vtkIdType>(patch.FileSupport.size()));
    }
    // Elements with empty support lists: the writer omitted them; do not check.
    bool anyEmpty = false;
    for (vtkIdType e = 0; e < ne; ++e)
    {
      anyEmpty = anyEmpty || patch.FileSupportOffsets[e + 1] == patch.FileSupportOffsets[e];
    }
    if (anyEmpty && patch.FileSupport.empty())
    {
      patch.FileSupportOffsets.clear();
    }
  }

  Tokenizer Tok;
};

//------------------------------------------------------------------------------
// GoTools g2, class 700
class G2Reader
{
public:
  G2Reader(const std::string& text)
    : Tok(text, false)
  {
  }

  Token Data(const std::string& context)
  {
    Token t = this->Tok.Next();
    if (t.Type == Token::End)
    {
      throw ParseError{ this->Tok.Line(),
        "unexpected end of file while reading " + context + " (the file is truncated)" };
    }
    if (t.Type == Token::Punct)
    {
      throw ParseError{ t.Line, "unexpected '" + t.Text + "' in " + context };
    }
    return t;
  }

  void Parse(std::vector<vtkLRSplinePatch>& patches)
  {
    while (this->Tok.Peek().Type != Token::End)
    {
      const Token classTok = this->Data("a g2 object header");
      const int line = classTok.Line;
      long long classType = 0;
      try
      {
        classType = ToInteger(classTok, "the GoTools class type", 0, 100000);
      }
      catch (const ParseError&)
      {
        throw ParseError{ line,
          "unknown header: expected a GoTools class type (700 for a "
          "SplineVolume), found " +
            Describe(classTok) };
      }
      if (classType != 700)
      {
        throw ParseError{ line,
          "GoTools class " + std::to_string(classType) +
            " is not supported; the reader reads class 700 (SplineVolume)" +
            (classType == 793 ? " (class 793, GoTools' LR volume, is not supported: save it in "
                                "the LRSplines text format instead)"
                              : "") };
      }
      const std::string hctx = "the g2 header (line " + std::to_string(line) + ")";
      ToInteger(this->Data(hctx), "the major version", 0, 1000);
      ToInteger(this->Data(hctx), "the minor version", 0, 1000);
      const long long nColour = ToInteger(this->Data(hctx), "the number of colour values", 0, 16);
      for (long long c = 0; c < nColour; ++c)
      {
        ToInteger(this->Data(hctx), "a colour value", -1000000, 1000000);
      }
      patches.emplace_back();
      vtkLRSplinePatch& patch = patches.back();
      patch.HeaderLine = line;
      this->ParseVolume(patch, static_cast<int>(patches.size()) - 1);
    }
    if (patches.empty())
    {
      throw ParseError{ this->Tok.Line(), "the file is empty (no g2 object)" };
    }
  }

private:
  void ParseVolume(vtkLRSplinePatch& patch, int index)
  {
    const std::string ctx = "volume " + std::to_string(index);
    const Token dimTok = this->Data(ctx);
    patch.Dimension = static_cast<int>(ToInteger(dimTok, ctx + ": dimension", 1, 64));
    const Token ratTok = this->Data(ctx);
    const int rational = static_cast<int>(ToInteger(ratTok, ctx + ": rational flag", 0, 1));
    if (rational)
    {
      throw ParseError{ ratTok.Line,
        ctx +
          " is rational (NURBS); only polynomial (rational = 0) "
          "g2 volumes are supported" };
    }
    long long n[3];
    std::vector<double> knots[3];
    const int maxOrder = vtkLRSplineBezierVolume::MaximumDegree + 1;
    for (int d = 0; d < 3; ++d)
    {
      const std::string dctx = ctx + ", direction " + "uvw"[d];
      n[d] = ToInteger(this->Data(dctx), dctx + ": number of coefficients", 1, 10000000);
      const Token orderTok = this->Data(dctx);
      patch.Order[d] = static_cast<int>(ToInteger(orderTok, dctx + ": order", 1, maxOrder));
      if (n[d] < patch.Order[d])
      {
        throw ParseError{ orderTok.Line, dctx + ": fewer coefficients than the order" };
      }
      const long long nk = n[d] + patch.Order[d];
      int firstLine = 0;
      for (long long k = 0; k < nk; ++k)
      {
        const Token t =
          this->Data(dctx + ": knot " + std::to_string(k) + " of " + std::to_string(nk));
        if (k == 0)
        {
          firstLine = t.Line;
        }
        const double v = ToNumber(t, dctx + ": knot");
        if (!std::isfinite(v))
        {
          throw ParseError{ t.Line, dctx + ": a knot is not a finite number" };
        }
        if (k > 0 && v < knots[d].back())
        {
          throw ParseError{ t.Line, dctx + ": the knot vector is not non-decreasing" };
        }
        knots[d].push_back(v);
      }
      const int p = patch.Order[d];
      // Clamped: the first and last `order` knots equal (the domain is the
      // whole knot span, every support inside it).
      if (knots[d][0] != knots[d][p - 1] || knots[d][nk - 1] != knots[d][nk - p])
      {
        throw ParseError{ firstLine,
          dctx +
            ": the knot vector is not clamped (open); only "
            "clamped knot vectors are supported" };
      }
      if (!(knots[d][0] < knots[d][nk - 1]))
      {
        throw ParseError{ firstLine, dctx + ": the knot vector spans an empty interval" };
      }
      for (long long k = 0; k < n[d]; ++k)
      {
        if (knots[d][k] == knots[d][k + p])
        {
          throw ParseError{ firstLine,
            dctx + ": basis function " + std::to_string(k) +
              " has an empty support (a knot has multiplicity greater than the order)" };
        }
      }
    }
    const double total = static_cast<double>(n[0]) * n[1] * n[2];
    if (total > 5.0e7)
    {
      throw ParseError{ dimTok.Line, ctx + ": too many coefficients" };
    }
    const vtkIdType nb = static_cast<vtkIdType>(total);
    const int kpf = patch.GetKnotsPerFunction();
    patch.Knots.reserve(std::min<std::size_t>(1 << 20, static_cast<std::size_t>(nb) * kpf));
    for (vtkIdType i = 0; i < nb; ++i)
    {
      const vtkIdType iu = i % n[0], iv = (i / n[0]) % n[1], iw = i / (n[0] * n[1]);
      const vtkIdType idx[3] = { iu, iv, iw };
      for (int d = 0; d < 3; ++d)
      {
        patch.Knots.insert(patch.Knots.end(), knots[d].begin() + idx[d],
          knots[d].begin() + idx[d] + patch.Order[d] + 1);
      }
      const std::string cctx =
        ctx + ": coefficient " + std::to_string(i) + " of " + std::to_string(nb);
      for (int c = 0; c < patch.Dimension; ++c)
      {
        const Token t = this->Data(cctx);
        if (c == 0)
        {
          patch.BasisLines.push_back(t.Line);
        }
        patch.Coefficients.push_back(ToNumber(t, cctx));
      }
      patch.Gamma.push_back(1.0);
    }
    // Elements: products of the non-empty knot intervals.
    std::vector<double> breaks[3];
    for (int d = 0; d < 3; ++d)
    {
      breaks[d] = knots[d];
      breaks[d].erase(std::unique(breaks[d].begin(), breaks[d].end()), breaks[d].end());
    }
    for (std::size_t k = 0; k + 1 < breaks[2].size(); ++k)
    {
      for (std::size_t j = 0; j + 1 < breaks[1].size(); ++j)
      {
        for (std::size_t i = 0; i + 1 < breaks[0].size(); ++i)
        {
          patch.ElementBoxes.insert(patch.ElementBoxes.end(),
            { breaks[0][i], breaks[1][j], breaks[2][k], breaks[0][i + 1], breaks[1][j + 1],
              breaks[2][k + 1] });
        }
      }
    }
    // Mesh rectangles (metadata): one full plane per distinct knot.
    double lo[3], hi[3];
    for (int d = 0; d < 3; ++d)
    {
      lo[d] = breaks[d].front();
      hi[d] = breaks[d].back();
    }
    for (int d = 0; d < 3; ++d)
    {
      for (double v : breaks[d])
      {
        double r[6] = { lo[0], lo[1], lo[2], hi[0], hi[1], hi[2] };
        r[d] = r[d + 3] = v;
        patch.MeshRectangles.insert(patch.MeshRectangles.end(), r, r + 6);
        patch.MeshMultiplicities.push_back(
          static_cast<int>(std::count(knots[d].begin(), knots[d].end(), v)));
      }
    }
  }

  Tokenizer Tok;
};
}

//------------------------------------------------------------------------------
int vtkLRSplineParser::DetectFormat(const std::string& text)
{
  for (char c : text)
  {
    if (std::isspace(static_cast<unsigned char>(c)))
    {
      continue;
    }
    if (c == '#')
    {
      return LRSPLINES;
    }
    if (std::isdigit(static_cast<unsigned char>(c)))
    {
      return G2;
    }
    return AUTOMATIC;
  }
  return AUTOMATIC;
}

namespace
{
/// Runs one of the format readers; a ParseError becomes `error` ("line N:
/// message") and an empty result.
template <typename Reader>
bool RunReader(const std::string& text, std::vector<vtkLRSplinePatch>& patches, std::string* error)
{
  patches.clear();
  try
  {
    Reader reader(text);
    reader.Parse(patches);
  }
  catch (const ParseError& e)
  {
    if (error)
    {
      *error = "line " + std::to_string(e.Line) + ": " + e.Message;
    }
    patches.clear();
    return false;
  }
  return true;
}
}

bool vtkLRSplineParser::ParseLRSplines(
  const std::string& text, std::vector<vtkLRSplinePatch>& patches, std::string* error)
{
  return RunReader<LRReader>(text, patches, error);
}

bool vtkLRSplineParser::ParseG2(
  const std::string& text, std::vector<vtkLRSplinePatch>& patches, std::string* error)
{
  return RunReader<G2Reader>(text, patches, error);
}

bool vtkLRSplineParser::Parse(
  const std::string& text, int format, std::vector<vtkLRSplinePatch>& patches, std::string* error)
{
  if (format == AUTOMATIC)
  {
    format = DetectFormat(text);
  }
  bool ok = false;
  if (format == LRSPLINES)
  {
    ok = ParseLRSplines(text, patches, error);
  }
  else if (format == G2)
  {
    ok = ParseG2(text, patches, error);
  }
  else
  {
    if (error)
    {
      // find the first line with content
      int line = 1;
      for (char c : text)
      {
        if (c == '\n')
        {
          ++line;
        }
        else if (!std::isspace(static_cast<unsigned char>(c)))
        {
          break;
        }
      }
      *error = "line " + std::to_string(line) +
        ": unknown header: neither an LRSplines file (\"# LRSPLINE VOLUME\") nor a GoTools g2 file";
      if (text.find_first_not_of(" \t\r\n") == std::string::npos)
      {
        *error = "line " + std::to_string(line) + ": the file is empty";
      }
    }
    return false;
  }
  if (!ok)
  {
    return false;
  }
  for (std::size_t p = 0; p < patches.size(); ++p)
  {
    std::string msg;
    if (!patches[p].Validate(&msg))
    {
      if (error)
      {
        *error = (msg.compare(0, 5, "line ") == 0 ? msg
                                                  : "line " +
              std::to_string(patches[p].HeaderLine) + ": patch " + std::to_string(p) + ": " + msg);
      }
      patches.clear();
      return false;
    }
  }
  return true;
}
