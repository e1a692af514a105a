// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLRSplineParser.h"

#include "vtkLRSplineBezierVolume.h"

#include <algorithm>
#include <array>
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
        if (w1 == "LRSPLINE" && (w2 == "VOLUME" || w2 == "SURFACE"))
        {
          patches.emplace_back();
          patches.back().HeaderLine = t.Line;
          this->ParsePatch(
            patches.back(), static_cast<int>(patches.size()) - 1, w2 == "VOLUME" ? 3 : 2);
          continue;
        }
        if (w1 == "LRSPLINE" && w2.empty())
        {
          throw ParseError{ t.Line,
            "\"# LRSPLINE\" without SURFACE or VOLUME is the pre-2013 surface format, which is "
            "not supported (expected \"# LRSPLINE SURFACE\" or \"# LRSPLINE VOLUME\")" };
        }
        if (w1 == "LRSPLINE")
        {
          throw ParseError{ t.Line,
            "unknown header " + Describe(t) +
              ", expected \"# LRSPLINE VOLUME\" or \"# LRSPLINE SURFACE\"" };
        }
        if (patches.empty() &&
          (w1.find("LRSPLINE") != std::string::npos || text.find("LRSPLINE") != std::string::npos))
        {
          throw ParseError{ t.Line,
            "unknown header " + Describe(t) +
              ", expected \"# LRSPLINE VOLUME\" or \"# LRSPLINE SURFACE\"" };
        }
        continue; // an ordinary comment
      }
      if (patches.empty())
      {
        throw ParseError{ t.Line,
          "unknown header: expected \"# LRSPLINE VOLUME\" or \"# LRSPLINE SURFACE\", found " +
            Describe(t) };
      }
      throw ParseError{ t.Line,
        "unexpected " + Describe(t) + " after the last element of patch " +
          std::to_string(patches.size() - 1) + " (wrong element count in its header?)" };
    }
    if (patches.empty())
    {
      throw ParseError{ this->Tok.Line(),
        "no LR-spline patch found (expected a \"# LRSPLINE VOLUME\" or \"# LRSPLINE SURFACE\" "
        "header)" };
    }
  }

private:
  // One patch after its "# LRSPLINE VOLUME" (pd 3) or "# LRSPLINE SURFACE" (pd 2)
  // header. A surface is stored with order 1 in w over [0, 1] (see vtkLRSplinePatch).
  void ParsePatch(vtkLRSplinePatch& patch, int index, int pd)
  {
    const std::string ctx = "the header of patch " + std::to_string(index);
    const int maxOrder = vtkLRSplineBezierVolume::MaximumDegree + 1;
    patch.ParametricDimension = pd;
    patch.Order[2] = 1;
    for (int d = 0; d < pd; ++d)
    {
      patch.Order[d] =
        static_cast<int>(this->Integer(ctx + ": order p" + std::to_string(d + 1), 1, maxOrder));
    }
    const long long maxCount = 100000000LL;
    const vtkIdType nb =
      static_cast<vtkIdType>(this->Integer(ctx + ": number of basis functions", 1, maxCount));
    const vtkIdType nl = static_cast<vtkIdType>(this->Integer(
      ctx + (pd == 3 ? ": number of mesh rectangles" : ": number of mesh lines"), 0, maxCount));
    const vtkIdType ne =
      static_cast<vtkIdType>(this->Integer(ctx + ": number of elements", 1, maxCount));
    patch.Dimension = static_cast<int>(this->Integer(ctx + ": dimension", 1, 64));
    patch.Rational = static_cast<int>(this->Integer(ctx + ": rational flag", 0, 1));

    const int kpf = patch.GetKnotsPerFunction();
    const std::size_t cap = 1 << 20; // never trust a count for allocation
    patch.Knots.reserve(std::min<std::size_t>(cap, static_cast<std::size_t>(nb) * kpf));
    for (vtkIdType i = 0; i < nb; ++i)
    {
      this->ParseBasisFunction(patch, index, i, nb);
    }
    for (vtkIdType r = 0; r < nl; ++r)
    {
      if (pd == 3)
      {
        this->ParseMeshRectangle(patch, index, r, nl);
      }
      else
      {
        this->ParseMeshLine(patch, index, r, nl);
      }
    }
    patch.FileSupportOffsets.push_back(0);
    for (vtkIdType e = 0; e < ne; ++e)
    {
      this->ParseElement(patch, index, e, ne);
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

  // "i: [knots u] x [knots v] (x [knots w]) c_1 ... c_dim (gamma)"
  void ParseBasisFunction(vtkLRSplinePatch& patch, int index, vtkIdType i, vtkIdType nb)
  {
    const int pd = patch.ParametricDimension;
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
    const long long id = ToInteger(idTok, bctx + ": id", 0, 100000000LL);
    if (id != i)
    {
      throw ParseError{ idTok.Line,
        "basis function ids must count 0, 1, 2, ...: expected " + std::to_string(i) + ", found " +
          std::to_string(id) };
    }
    this->Expect(":", bctx);
    for (int d = 0; d < pd; ++d)
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
    if (pd == 2)
    {
      patch.Knots.push_back(vtkLRSplinePatch::SurfaceW0);
      patch.Knots.push_back(vtkLRSplinePatch::SurfaceW1);
    }
    for (int c = 0; c < patch.Dimension; ++c)
    {
      patch.Coefficients.push_back(this->Number(bctx + ": coefficient"));
    }
    this->Expect("(", bctx + " (before gamma)");
    patch.Gamma.push_back(this->Number(bctx + ": gamma"));
    this->Expect(")", bctx + " (after gamma)");
  }

  // "[a, b] x [c, d] x [e, f] (m)"
  void ParseMeshRectangle(vtkLRSplinePatch& patch, int index, vtkIdType r, vtkIdType nl)
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
    this->AddMeshRectangle(patch, lo, hi, 3, this->Multiplicity(rctx), line, rctx);
  }

  // "c x [s, e] (m)" (u constant) or "[s, e] x c (m)" (v constant)
  void ParseMeshLine(vtkLRSplinePatch& patch, int index, vtkIdType r, vtkIdType nl)
  {
    const std::string rctx = "mesh line " + std::to_string(r) + " of " + std::to_string(nl) +
      " (patch " + std::to_string(index) + ")";
    double lo[3] = { 0, 0, vtkLRSplinePatch::SurfaceW0 };
    double hi[3] = { 0, 0, vtkLRSplinePatch::SurfaceW1 };
    Token first = this->Data(rctx);
    const int line = first.Line;
    if (first.Text == "[")
    {
      lo[0] = this->Number(rctx);
      this->Expect(",", rctx);
      hi[0] = this->Number(rctx);
      this->Expect("]", rctx);
      this->Expect("x", rctx);
      lo[1] = hi[1] = this->Number(rctx);
    }
    else
    {
      if (first.Type != Token::Word || first.Text == "x")
      {
        throw ParseError{ line, "expected a mesh line in " + rctx + ", found " + Describe(first) };
      }
      lo[0] = hi[0] = ToNumber(first,
        rctx +
          (r == 0 ? " (wrong basis function count in the header?)"
                  : " (wrong mesh line count in the header?)"));
      this->Expect("x", rctx);
      this->Expect("[", rctx);
      lo[1] = this->Number(rctx);
      this->Expect(",", rctx);
      hi[1] = this->Number(rctx);
      this->Expect("]", rctx);
    }
    this->AddMeshRectangle(patch, lo, hi, 2, this->Multiplicity(rctx), line, rctx);
  }

  int Multiplicity(const std::string& ctx)
  {
    this->Expect("(", ctx);
    const int m = static_cast<int>(this->Integer(ctx + ": multiplicity", 1, 64));
    this->Expect(")", ctx);
    return m;
  }

  static void AddMeshRectangle(vtkLRSplinePatch& patch, const double lo[3], const double hi[3],
    int pd, int m, int line, const std::string& ctx)
  {
    int flat = 0;
    for (int d = 0; d < pd; ++d)
    {
      if (!std::isfinite(lo[d]) || !std::isfinite(hi[d]) || hi[d] < lo[d])
      {
        throw ParseError{ line, ctx + ": invalid interval" };
      }
      flat += lo[d] == hi[d] ? 1 : 0;
    }
    if (flat != 1)
    {
      throw ParseError{ line, ctx + ": exactly one direction must be constant (start = stop)" };
    }
    patch.MeshRectangles.insert(
      patch.MeshRectangles.end(), { lo[0], lo[1], lo[2], hi[0], hi[1], hi[2] });
    patch.MeshMultiplicities.push_back(m);
  }

  // "e [pd] : (lo...) x (hi...)    {support}"
  void ParseElement(vtkLRSplinePatch& patch, int index, vtkIdType e, vtkIdType ne)
  {
    const int pd = patch.ParametricDimension;
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
    const long long id = ToInteger(idTok, ectx + ": id", 0, 100000000LL);
    if (id != e)
    {
      throw ParseError{ idTok.Line,
        "element ids must count 0, 1, 2, ...: expected " + std::to_string(e) + ", found " +
          std::to_string(id) };
    }
    this->Expect("[", ectx);
    const Token dimTok = this->Data(ectx);
    if (ToInteger(dimTok, ectx + ": parametric dimension", 0, 1000) != pd)
    {
      throw ParseError{ dimTok.Line,
        ectx + ": parametric dimension must be " + std::to_string(pd) };
    }
    this->Expect("]", ectx);
    this->Expect(":", ectx);
    double box[6] = { 0, 0, vtkLRSplinePatch::SurfaceW0, 0, 0, vtkLRSplinePatch::SurfaceW1 };
    for (int corner = 0; corner < 2; ++corner)
    {
      if (corner == 1)
      {
        this->Expect("x", ectx);
      }
      this->Expect("(", ectx);
      for (int d = 0; d < pd; ++d)
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
          static_cast<vtkIdType>(ToInteger(t, ectx + ": basis function index", 0, 100000000LL)));
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

  Tokenizer Tok;
};

//------------------------------------------------------------------------------
// A mesh rectangle of a GoTools LR mesh in the plane (direction d, distinct
// knot p): the knot intervals [LoA, HiA) x [LoB, HiB) of the two other
// directions a = (d + 1) % 3, b = (d + 2) % 3, and its multiplicity.
struct PlaneRect
{
  long long LoA, LoB, HiA, HiB;
  int Mult;
};

// Is the face (ja, jb) of plane p covered by a rectangle of positive multiplicity?
bool FaceInMesh(const std::vector<PlaneRect>& plane, long long ja, long long jb)
{
  for (const PlaneRect& r : plane)
  {
    if (r.Mult > 0 && r.LoA <= ja && ja < r.HiA && r.LoB <= jb && jb < r.HiB)
    {
      return true;
    }
  }
  return false;
}

// The elements of an LR mesh given by its distinct knots per direction and its
// mesh rectangles per plane. The tensor grid of distinct knots is swept in
// order (u fastest); the first cell not yet in an element is the lowest corner
// of the next one, which extends in u, then v, then w up to the first mesh
// rectangle. A bitmap of the grid cells checks that the elements do not
// overlap and cover the domain. Elements are ordered by their lowest corner.
void ElementsFromMesh(const std::vector<double> knots[3],
  const std::vector<std::vector<PlaneRect>> planes[3], vtkLRSplinePatch& patch, int line)
{
  long long n[3];
  for (int d = 0; d < 3; ++d)
  {
    n[d] = static_cast<long long>(knots[d].size()) - 1; // intervals
  }
  std::vector<bool> covered(static_cast<std::size_t>(n[0] * n[1] * n[2]), false);
  auto cell = [&n](long long i, long long j, long long k) { return i + n[0] * (j + n[1] * k); };
  // Is there a mesh face between cell c and its neighbour in direction d?
  auto wall = [&](int d, const long long c[3])
  {
    const int a = (d + 1) % 3, b = (d + 2) % 3;
    return FaceInMesh(planes[d][c[d] + 1], c[a], c[b]);
  };
  for (long long k = 0; k < n[2]; ++k)
  {
    for (long long j = 0; j < n[1]; ++j)
    {
      for (long long i = 0; i < n[0]; ++i)
      {
        if (covered[cell(i, j, k)])
        {
          continue;
        }
        long long lo[3] = { i, j, k }, hi[3] = { i, j, k };
        for (int d = 0; d < 3; ++d)
        {
          long long c[3] = { i, j, k };
          while (hi[d] + 1 < n[d])
          {
            c[d] = hi[d];
            if (wall(d, c))
            {
              break;
            }
            ++hi[d];
          }
        }
        double box[6];
        for (int d = 0; d < 3; ++d)
        {
          box[d] = knots[d][lo[d]];
          box[d + 3] = knots[d][hi[d] + 1];
        }
        for (long long z = lo[2]; z <= hi[2]; ++z)
        {
          for (long long y = lo[1]; y <= hi[1]; ++y)
          {
            for (long long x = lo[0]; x <= hi[0]; ++x)
            {
              if (covered[cell(x, y, z)])
              {
                throw ParseError{ line,
                  "the LR mesh does not partition the domain into boxes (the element at (" +
                    std::to_string(box[0]) + ", " + std::to_string(box[1]) + ", " +
                    std::to_string(box[2]) + ") overlaps another)" };
              }
              covered[cell(x, y, z)] = true;
            }
          }
        }
        patch.ElementBoxes.insert(patch.ElementBoxes.end(), box, box + 6);
      }
    }
  }
}

//------------------------------------------------------------------------------
// GoTools g2: classes 200 / 700 (tensor-product spline surface / volume) and
// 293 / 793 (GoTools' LR spline surface / volume).
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
  long long Int(const std::string& context, long long lo, long long hi)
  {
    return ToInteger(this->Data(context), context, lo, hi);
  }
  double Finite(const std::string& context)
  {
    const Token t = this->Data(context);
    const double v = ToNumber(t, context);
    if (!std::isfinite(v))
    {
      throw ParseError{ t.Line, context + ": a value is not a finite number" };
    }
    return v;
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
          "unknown header: expected a GoTools class type (200, 700, 293 or 793), found " +
            Describe(classTok) };
      }
      if (classType != 200 && classType != 700 && classType != 293 && classType != 793)
      {
        throw ParseError{ line,
          "GoTools class " + std::to_string(classType) +
            " is not supported; the reader reads classes 200 (SplineSurface), 700 "
            "(SplineVolume), 293 (LRSplineSurface) and 793 (LRSplineVolume)" +
            (classType == 100 ? " (class 100 is a curve)" : "") };
      }
      const std::string hctx = "the g2 header (line " + std::to_string(line) + ")";
      this->Int(hctx + ": the major version", 0, 1000);
      this->Int(hctx + ": the minor version", 0, 1000);
      const long long nColour = this->Int(hctx + ": the number of colour values", 0, 16);
      for (long long c = 0; c < nColour; ++c)
      {
        this->Int(hctx + ": a colour value", -1000000, 1000000);
      }
      patches.emplace_back();
      vtkLRSplinePatch& patch = patches.back();
      patch.HeaderLine = line;
      const int pd = (classType == 200 || classType == 293) ? 2 : 3;
      const int index = static_cast<int>(patches.size()) - 1;
      if (classType == 200 || classType == 700)
      {
        this->ParseTensor(patch, index, pd);
      }
      else
      {
        this->ParseLR(patch, index, pd, line);
      }
    }
    if (patches.empty())
    {
      throw ParseError{ this->Tok.Line(), "the file is empty (no g2 object)" };
    }
  }

private:
  // One clamped knot vector of n functions of the given order.
  void ParseKnotVector(const std::string& dctx, long long n, int order, std::vector<double>& knots)
  {
    const long long nk = n + order;
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
      if (k > 0 && v < knots.back())
      {
        throw ParseError{ t.Line, dctx + ": the knot vector is not non-decreasing" };
      }
      knots.push_back(v);
    }
    // Clamped: the first and last `order` knots equal (the domain is the
    // whole knot span, every support inside it).
    if (knots[0] != knots[order - 1] || knots[nk - 1] != knots[nk - order])
    {
      throw ParseError{ firstLine,
        dctx + ": the knot vector is not clamped (open); only clamped knot vectors are supported" };
    }
    if (!(knots[0] < knots[nk - 1]))
    {
      throw ParseError{ firstLine, dctx + ": the knot vector spans an empty interval" };
    }
    for (long long k = 0; k < n; ++k)
    {
      if (knots[k] == knots[k + order])
      {
        throw ParseError{ firstLine,
          dctx + ": basis function " + std::to_string(k) +
            " has an empty support (a knot has multiplicity greater than the order)" };
      }
    }
  }

  // Classes 200 and 700: dim rational, then per direction "n order knots",
  // then the coefficients (u fastest), dim + 1 homogeneous values each when
  // rational.
  void ParseTensor(vtkLRSplinePatch& patch, int index, int pd)
  {
    const std::string ctx = (pd == 3 ? "volume " : "surface ") + std::to_string(index);
    const Token dimTok = this->Data(ctx);
    const int dim = static_cast<int>(ToInteger(dimTok, ctx + ": dimension", 1, 63));
    const int rational = static_cast<int>(this->Int(ctx + ": rational flag", 0, 1));
    patch.ParametricDimension = pd;
    patch.Rational = rational;
    patch.RationalCoefficients = rational == 1;
    patch.ExplicitRational = true;
    patch.Dimension = dim + rational;
    long long n[3] = { 1, 1, 1 };
    std::vector<double> knots[3];
    if (pd == 2)
    {
      knots[2] = { vtkLRSplinePatch::SurfaceW0, vtkLRSplinePatch::SurfaceW1 };
    }
    patch.Order[2] = 1;
    const int maxOrder = vtkLRSplineBezierVolume::MaximumDegree + 1;
    for (int d = 0; d < pd; ++d)
    {
      const std::string dctx = ctx + ", direction " + "uvw"[d];
      n[d] = this->Int(dctx + ": number of coefficients", 1, 10000000);
      const Token orderTok = this->Data(dctx);
      patch.Order[d] = static_cast<int>(ToInteger(orderTok, dctx + ": order", 1, maxOrder));
      if (n[d] < patch.Order[d])
      {
        throw ParseError{ orderTok.Line, dctx + ": fewer coefficients than the order" };
      }
      this->ParseKnotVector(dctx, n[d], patch.Order[d], knots[d]);
    }
    const double total = static_cast<double>(n[0]) * n[1] * n[2];
    if (total > 5.0e7 || total * patch.Dimension > 2.0e8)
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
    // Elements: products of the non-empty knot intervals; mesh rectangles
    // (metadata): one full plane per distinct knot.
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
    for (int d = 0; d < pd; ++d)
    {
      for (double v : breaks[d])
      {
        double r[6] = { breaks[0].front(), breaks[1].front(), breaks[2].front(), breaks[0].back(),
          breaks[1].back(), breaks[2].back() };
        r[d] = r[d + 3] = v;
        patch.MeshRectangles.insert(patch.MeshRectangles.end(), r, r + 6);
        patch.MeshMultiplicities.push_back(
          static_cast<int>(std::count(knots[d].begin(), knots[d].end(), v)));
      }
    }
  }

  // Classes 293 and 793 (GoTools' LRSplineSurface / LRSplineVolume::write):
  // rational flag, knot tolerance; the mesh: per direction the distinct knots
  // (count, values), then per direction and distinct knot the mesh rectangles
  // in that plane (count, then per rectangle: surfaces "ix mult", the
  // multiplicity from knot interval ix of the other direction on, until the
  // next; volumes "ll_a ll_b ur_a ur_b mult" over the knot indices of the two
  // other directions a = d+1, b = d+2 cyclically); the number of basis
  // functions, and per function: "dim rat", dim coefficients times gamma,
  // gamma, weight, and per direction its knots as indices into the distinct
  // knots (count, indices).
  void ParseLR(vtkLRSplinePatch& patch, int index, int pd, int line)
  {
    const std::string ctx = (pd == 3 ? "LR volume " : "LR surface ") + std::to_string(index);
    patch.ParametricDimension = pd;
    patch.Order[2] = 1;
    const int rational = static_cast<int>(this->Int(ctx + ": rational flag", 0, 1));
    this->Finite(ctx + ": knot tolerance");
    std::vector<double> knots[3];
    if (pd == 2)
    {
      knots[2] = { vtkLRSplinePatch::SurfaceW0, vtkLRSplinePatch::SurfaceW1 };
    }
    for (int d = 0; d < pd; ++d)
    {
      const std::string dctx = ctx + ": distinct knots in " + "uvw"[d];
      const long long nk = this->Int(dctx + " (count)", 2, 1000000);
      for (long long k = 0; k < nk; ++k)
      {
        knots[d].push_back(this->Finite(dctx));
        if (k > 0 && !(knots[d][k] > knots[d][k - 1]))
        {
          throw ParseError{ this->Tok.Line(), dctx + " are not strictly increasing" };
        }
      }
    }
    const double cells =
      static_cast<double>(knots[0].size() - 1) * (knots[1].size() - 1) * (knots[2].size() - 1);
    if (cells > 6.4e7)
    {
      throw ParseError{ line,
        ctx + ": the tensor grid of the distinct knots has too many cells (more than 6.4e7)" };
    }
    std::vector<std::vector<PlaneRect>> planes[3];
    for (int d = 0; d < 3; ++d)
    {
      this->ParseLRPlanes(patch, ctx, pd, d, knots, planes[d]);
    }
    ElementsFromMesh(knots, planes, patch, line);
    this->ParseLRFunctions(patch, ctx, knots, rational);
  }

  // The mesh rectangles of direction d (one list per distinct knot of d).
  void ParseLRPlanes(vtkLRSplinePatch& patch, const std::string& ctx, int pd, int d,
    const std::vector<double> knots[3], std::vector<std::vector<PlaneRect>>& planes)
  {
    const int a = (d + 1) % 3, b = (d + 2) % 3;
    const long long na = static_cast<long long>(knots[a].size()) - 1;
    const long long nb = static_cast<long long>(knots[b].size()) - 1;
    const std::size_t np = knots[d].size();
    planes.assign(np, std::vector<PlaneRect>());
    if (d >= pd)
    {
      return; // a surface's w direction has no interior planes
    }
    const std::string dctx = ctx + ": mesh rectangles with " + "uvw"[d] + " constant";
    if (this->Int(dctx + " (number of planes)", 0, 1000000) != static_cast<long long>(np))
    {
      throw ParseError{ this->Tok.Line(), dctx + ": one list per distinct knot expected" };
    }
    for (std::size_t p = 0; p < np; ++p)
    {
      std::vector<PlaneRect>& plane = planes[p];
      const long long count = this->Int(dctx + " (count)", 0, 100000000);
      for (long long r = 0; r < count; ++r)
      {
        PlaneRect rect{ 0, 0, na, nb, 0 };
        if (pd == 2)
        {
          // Runs "ix mult" along the other direction (v for d = 0, u for d = 1):
          // the multiplicity from knot interval ix on, until the next run.
          const long long nOther = d == 0 ? na : nb;
          const long long ix = this->Int(dctx + ": start index", 0, nOther - 1);
          rect.Mult = static_cast<int>(this->Int(dctx + ": multiplicity", 0, 64));
          if (!plane.empty())
          {
            PlaneRect& previous = plane.back();
            long long& end = d == 0 ? previous.HiA : previous.HiB;
            const long long start = d == 0 ? previous.LoA : previous.LoB;
            if (ix <= start)
            {
              throw ParseError{ this->Tok.Line(), dctx + ": start indices must increase" };
            }
            end = ix;
          }
          (d == 0 ? rect.LoA : rect.LoB) = ix;
        }
        else
        {
          rect.LoA = this->Int(dctx + ": lower corner", 0, na - 1);
          rect.LoB = this->Int(dctx + ": lower corner", 0, nb - 1);
          rect.HiA = this->Int(dctx + ": upper corner", rect.LoA + 1, na);
          rect.HiB = this->Int(dctx + ": upper corner", rect.LoB + 1, nb);
          rect.Mult = static_cast<int>(this->Int(dctx + ": multiplicity", 0, 64));
        }
        plane.push_back(rect);
      }
      // The patch's mesh rectangles (metadata): those of positive multiplicity.
      for (const PlaneRect& r : plane)
      {
        if (r.Mult > 0)
        {
          double box[6];
          box[d] = box[d + 3] = knots[d][p];
          box[a] = knots[a][r.LoA];
          box[a + 3] = knots[a][r.HiA];
          box[b] = knots[b][r.LoB];
          box[b + 3] = knots[b][r.HiB];
          patch.MeshRectangles.insert(patch.MeshRectangles.end(), box, box + 6);
          patch.MeshMultiplicities.push_back(r.Mult);
        }
      }
    }
  }

  void ParseLRFunctions(vtkLRSplinePatch& patch, const std::string& ctx,
    const std::vector<double> knots[3], int rational)
  {
    const int pd = patch.ParametricDimension;
    const long long nb = this->Int(ctx + ": number of basis functions", 1, 100000000);
    const int maxOrder = vtkLRSplineBezierVolume::MaximumDegree + 1;
    int dim = 0;
    std::vector<double> weights;
    std::vector<int> flags;
    for (long long i = 0; i < nb; ++i)
    {
      const std::string bctx =
        ctx + ": basis function " + std::to_string(i) + " of " + std::to_string(nb);
      const Token first = this->Data(bctx);
      patch.BasisLines.push_back(first.Line);
      const int di = static_cast<int>(ToInteger(first, bctx + ": dimension", 1, 63));
      if (i == 0)
      {
        dim = di;
      }
      else if (di != dim)
      {
        throw ParseError{ first.Line, bctx + ": its dimension differs from the first function's" };
      }
      flags.push_back(static_cast<int>(this->Int(bctx + ": rational flag", 0, 1)));
      double c[64];
      for (int k = 0; k < dim; ++k)
      {
        c[k] = ToNumber(this->Data(bctx), bctx + ": coefficient");
      }
      const double gamma = ToNumber(this->Data(bctx), bctx + ": gamma");
      weights.push_back(ToNumber(this->Data(bctx), bctx + ": weight"));
      for (int k = 0; k < dim; ++k)
      {
        // The file holds the coefficient times gamma.
        patch.Coefficients.push_back(c[k] / gamma);
      }
      patch.Gamma.push_back(gamma);
      for (int d = 0; d < pd; ++d)
      {
        const std::string kctx = bctx + ": knot indices in " + "uvw"[d];
        const int count = static_cast<int>(this->Int(kctx + " (count)", 2, maxOrder + 1));
        if (i == 0)
        {
          patch.Order[d] = count - 1;
        }
        else if (count - 1 != patch.Order[d])
        {
          throw ParseError{ this->Tok.Line(),
            kctx + ": its order differs from the first function's" };
        }
        long long previous = 0;
        for (int k = 0; k < count; ++k)
        {
          const long long ix = this->Int(kctx, 0, static_cast<long long>(knots[d].size()) - 1);
          if (ix < previous)
          {
            throw ParseError{ this->Tok.Line(), kctx + " are not non-decreasing" };
          }
          previous = ix;
          patch.Knots.push_back(knots[d][ix]);
        }
      }
      if (pd == 2)
      {
        patch.Knots.push_back(vtkLRSplinePatch::SurfaceW0);
        patch.Knots.push_back(vtkLRSplinePatch::SurfaceW1);
      }
    }
    const bool isRational =
      rational == 1 || std::find(flags.begin(), flags.end(), 1) != flags.end();
    patch.Rational = isRational ? 1 : 0;
    patch.ExplicitRational = true;
    patch.Dimension = dim;
    if (isRational)
    {
      // Homogeneous form (w c, w), the convention of vtkLRSplinePatch.
      std::vector<double> h;
      h.reserve(patch.Coefficients.size() + weights.size());
      for (std::size_t i = 0; i < weights.size(); ++i)
      {
        for (int k = 0; k < dim; ++k)
        {
          h.push_back(weights[i] * patch.Coefficients[i * dim + k]);
        }
        h.push_back(weights[i]);
      }
      patch.Coefficients.swap(h);
      patch.Dimension = dim + 1;
      patch.RationalCoefficients = true;
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
