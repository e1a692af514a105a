// SPDX-License-Identifier: BSD-3-Clause
// vtkLRSplineReader on bad input: each case must give an error (RequestData
// fails, the output is empty) whose message names the right line, never a
// crash, a hang or silent garbage. Cases: truncated files, wrong counts,
// unknown headers, NaN/inf numbers, knot vectors of the wrong length,
// inconsistent meshes and support lists, a non-existent file, an empty
// file, broken surfaces, g2 variants; and a fuzz run of random mutations of the
// real file (must succeed with finite output or fail with a message).
#include "vtkLRSplineReader.h"

#include "LRSplineTestUtilities.h"
#include "SplineVizTestUtilities.h"

#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkTestErrorObserver.h"
#include "vtkUnstructuredGrid.h"

#include <chrono>
#include <cmath>
#include <fstream>
#include <random>
#include <sstream>

namespace
{
const std::string OutDir = SPLINEVIZ_TEST_OUTPUT_DIR;

std::vector<std::string> SplitLines(const std::string& text)
{
  std::vector<std::string> lines;
  std::istringstream in(text);
  std::string l;
  while (std::getline(in, l))
  {
    lines.push_back(l);
  }
  return lines;
}

std::string JoinLines(const std::vector<std::string>& lines)
{
  std::string s;
  for (const auto& l : lines)
  {
    s += l;
    s += '\n';
  }
  return s;
}

struct Result
{
  bool Ok;
  std::string Message;
  vtkMultiBlockDataSet* Output;
};

// Read a text through a file; the reader reports the error (observed so it
// does not pollute the log).
class Harness
{
public:
  Harness()
  {
    this->Reader->AddObserver(vtkCommand::ErrorEvent, this->Observer);
    this->Reader->AddObserver(vtkCommand::WarningEvent, this->Observer);
    this->Reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, this->Observer);
  }
  Result ReadText(const std::string& text, const std::string& ext = ".lr")
  {
    const std::string path = OutDir + "/TestLRSplineReaderBadInput" + ext;
    {
      std::ofstream out(path, std::ios::binary);
      out << text;
    }
    return this->ReadFile(path);
  }
  Result ReadFile(const std::string& path)
  {
    this->Reader->SetFileName(path.c_str());
    this->Reader->Modified();
    this->Observer->Clear();
    const int ok = this->Reader->GetExecutive()->Update();
    return Result{ ok != 0, this->Reader->GetLastErrorMessage(), this->Reader->GetOutput() };
  }
  vtkNew<vtkLRSplineReader> Reader;
  vtkNew<vtkTest::ErrorObserver> Observer;
};

void ExpectError(SplineVizTestStatus& status, const Result& r, const std::string& what,
  const std::string& expectText, int expectLine)
{
  const bool hasText = r.Message.find(expectText) != std::string::npos;
  const std::string lineText = "line " + std::to_string(expectLine) + ":";
  const bool hasLine = expectLine <= 0 || r.Message.find(lineText) != std::string::npos;
  SV_CHECK_MSG(status, !r.Ok, what << ": the read did not fail");
  SV_CHECK_MSG(
    status, hasText, what << ": message \"" << r.Message << "\" lacks \"" << expectText << "\"");
  SV_CHECK_MSG(
    status, hasLine, what << ": message \"" << r.Message << "\" lacks \"" << lineText << "\"");
  SV_CHECK_MSG(status, r.Output->GetNumberOfBlocks() == 0, what << ": output not empty");
  std::cout << what << ": " << r.Message << std::endl;
}

std::string ReplaceLine(std::vector<std::string> lines, int line, const std::string& text)
{
  lines[line - 1] = text;
  return JoinLines(lines);
}
}

int TestLRSplineReaderBadInput(int, char*[])
{
  SplineVizTestStatus status;
  Harness h;
  const std::string real =
    lrtest::ReadText(std::string(SPLINEVIZ_EXTERNAL_DATA_DIR) + "/cube-3patch-refined.lr");
  const std::vector<std::string> lines = SplitLines(real);
  // The first patch alone (its lines 1..2612): fast to read in the fuzz loop.
  std::vector<std::string> first(lines.begin(), lines.begin() + 2612);
  const std::string firstText = JoinLines(first);
  {
    Result r = h.ReadText(firstText);
    SV_CHECK_MSG(status, r.Ok, r.Message);
  }
  // Line numbers (1-based) in the real file: basis function i of patch 0 is
  // on line 5 + i, mesh rectangles start at 1182, elements at 1372.
  SV_CHECK(status, lines[4 + 17].compare(0, 4, "17: ") == 0);
  SV_CHECK(status, lines[1371].compare(0, 6, "0 [3] ") == 0);

  // Missing, empty and non-text files.
  ExpectError(status, h.ReadFile(OutDir + "/does-not-exist.lr"), "missing file", "cannot open", 0);
  ExpectError(status, h.ReadText(""), "empty file", "empty", 1);
  ExpectError(status, h.ReadText("\n\n   \n"), "blank file", "empty", 0);
  ExpectError(
    status, h.ReadText(std::string("\x01\x02\x00\xff", 4)), "binary file", "unknown header", 1);

  // A surface reads (TestLRSplineReader checks its values); broken surfaces do not.
  {
    const std::string surface =
      lrtest::ReadText(std::string(SPLINEVIZ_EXTERNAL_DATA_DIR) + "/surface-refined.lr");
    const std::vector<std::string> sl = SplitLines(surface);
    Result ok = h.ReadText(surface);
    SV_CHECK_MSG(status, ok.Ok, ok.Message);
    SV_CHECK(status, sl[1365].compare(0, 6, "0 [2] ") == 0 && sl[1234].compare(0, 2, "0 ") == 0);
    ExpectError(status,
      h.ReadText(ReplaceLine(sl, 1366, "0 [3] : (0, 0) x (0.125, 0.125)    {0, 4, 275, 277}")),
      "surface element [3]", "parametric dimension must be 2", 1366);
    ExpectError(status, h.ReadText(ReplaceLine(sl, 1235, "0 x [0 1] (2)")), "surface mesh line",
      "expected ','", 1235);
    ExpectError(status, h.ReadText(ReplaceLine(sl, 1235, "[0, 1] x [0, 1] (2)")),
      "surface mesh line with two intervals", "expected a number", 1235);
    ExpectError(status,
      h.ReadText(ReplaceLine(sl, 5, "0: [0 0 0.125 ] x [0 0 0.125 ] x [0 0 1] 0 0 (1)")),
      "surface basis function with three knot vectors", "found \"x\"", 5);
  }

  // Unknown headers.
  ExpectError(status, h.ReadText(ReplaceLine(first, 1, "# LRSPLINE CURVE")),
    "unknown LRSPLINE kind", "unknown header", 1);
  ExpectError(status, h.ReadText(ReplaceLine(first, 1, "# some other file")), "unknown header",
    "unknown header", 3);
  ExpectError(
    status, h.ReadText("hello world\n" + firstText), "text before the header", "unknown header", 1);
  ExpectError(
    status, h.ReadText(ReplaceLine(first, 1, "# LRSPLINE")), "pre-2013 header", "pre-2013", 1);

  // Truncated: at a line boundary inside the basis functions, inside a
  // line of the elements, in the middle of a number.
  {
    std::vector<std::string> cut(first.begin(), first.begin() + 600);
    ExpectError(status, h.ReadText(JoinLines(cut)), "truncated (basis)", "truncated", 600);
    cut.assign(first.begin(), first.begin() + 1400);
    cut.back() = cut.back().substr(0, cut.back().size() / 2);
    ExpectError(status, h.ReadText(JoinLines(cut)), "truncated (element)", "truncated", 1400);
    const std::string mid = firstText.substr(0, firstText.size() / 3);
    const int line = static_cast<int>(std::count(mid.begin(), mid.end(), '\n')) + 1;
    ExpectError(status, h.ReadText(mid), "truncated (middle)", "", line);
    ExpectError(status,
      h.ReadText(JoinLines(std::vector<std::string>(first.begin(), first.begin() + 2))),
      "header only", "truncated", 2);
  }

  // Wrong counts in the header (3 3 3 1176 189 1240 3 0).
  ExpectError(status, h.ReadText(ReplaceLine(first, 3, "\t3\t3\t3\t1177\t189\t1240\t3\t0")),
    "Nbasis + 1", "wrong basis function count", 1182);
  ExpectError(status, h.ReadText(ReplaceLine(first, 3, "\t3\t3\t3\t1175\t189\t1240\t3\t0")),
    "Nbasis - 1", "wrong basis function count", 1180);
  ExpectError(status, h.ReadText(ReplaceLine(first, 3, "\t3\t3\t3\t1176\t190\t1240\t3\t0")),
    "Nline + 1", "wrong mesh rectangle count", 1372);
  ExpectError(status, h.ReadText(ReplaceLine(first, 3, "\t3\t3\t3\t1176\t189\t1239\t3\t0")),
    "Nel - 1", "wrong element count", 2611);
  ExpectError(status, h.ReadText(ReplaceLine(first, 3, "\t3\t3\t3\t1176\t189\t1241\t3\t0")),
    "Nel + 1 (last patch)", "truncated", 2611);
  ExpectError(status,
    h.ReadText(JoinLines(SplitLines(ReplaceLine(lines, 3, "\t3\t3\t3\t1176\t189\t1241\t3\t0")))),
    "Nel + 1 (next patch follows)", "new patch header", 2613);
  ExpectError(status, h.ReadText(ReplaceLine(first, 3, "\t3\t3\t3\t-5\t189\t1240\t3\t0")),
    "negative count", "number of basis functions is -5", 3);
  ExpectError(status, h.ReadText(ReplaceLine(first, 3, "\t3\t3\t3\t99999999999\t189\t1240\t3\t0")),
    "huge count", "number of basis functions", 3);
  ExpectError(status, h.ReadText(ReplaceLine(first, 3, "\t3\t3\t3\t1176\t189\t1240\t0\t0")),
    "dimension 0", "dimension", 3);
  ExpectError(status, h.ReadText(ReplaceLine(first, 3, "\t3\t3\t99\t1176\t189\t1240\t3\t0")),
    "order 99", "order p3", 3);

  // Non-finite numbers, naming their line.
  {
    std::string l = first[4 + 17];
    const std::size_t pos = l.rfind("] ") + 2;
    ExpectError(status,
      h.ReadText(ReplaceLine(first, 22, l.substr(0, pos) + "nan" + l.substr(l.find(' ', pos)))),
      "NaN coefficient", "coefficient 0 is not a finite number", 22);
    ExpectError(status,
      h.ReadText(ReplaceLine(first, 22,
        "17: [0 0 nan 0.0625 ] x [0 0 0.0625 0.125 ] x [0 0.0625 0.125 0.1875 ] 0 0 0 (1)")),
      "NaN knot", "not a finite number", 22);
    ExpectError(status, h.ReadText(ReplaceLine(first, 22, l.substr(0, l.rfind('(')) + "(inf)")),
      "infinite gamma", "gamma", 22);
    ExpectError(status, h.ReadText(ReplaceLine(first, 22, l.substr(0, l.rfind('(')) + "(0)")),
      "zero gamma", "gamma", 22);
    ExpectError(status, h.ReadText(ReplaceLine(first, 22, l.substr(0, l.rfind('(')) + "(abc)")),
      "non-number gamma", "expected a number", 22);
  }

  // Knot vectors of the wrong length; decreasing knots.
  {
    ExpectError(status,
      h.ReadText(ReplaceLine(
        first, 35, "30: [0 0 0.0625 ] x [0 0 0.0625 0.125 ] x [0 0.0625 0.125 0.1875 ] 0 0 0 (1)")),
      "short knot vector", "knot vector u has 3 values, expected order + 1 = 4", 35);
    ExpectError(status,
      h.ReadText(ReplaceLine(first, 35,
        "30: [0 0 0.0625 0.125 ] x [0 0 0.0625 0.125 0.1875 ] x [0 0.0625 0.125 0.1875 ] 0 0 0 "
        "(1)")),
      "long knot vector", "knot vector v has more than order + 1 = 4 values", 35);
    ExpectError(status,
      h.ReadText(ReplaceLine(first, 35,
        "30: [0 0.125 0.0625 0.125 ] x [0 0 0.0625 0.125 ] x [0 0.0625 0.125 0.1875 ] 0 0 0 (1)")),
      "decreasing knots", "not non-decreasing", 35);
    ExpectError(status,
      h.ReadText(ReplaceLine(first, 35,
        "31: [0 0 0.0625 0.125 ] x [0 0 0.0625 0.125 ] x [0 0.0625 0.125 0.1875 ] 0 0 0 (1)")),
      "wrong id", "expected 30, found 31", 35);
  }

  // Meshes that do not match: a moved element corner, a wrong support list,
  // a basis function whose knots cut through elements.
  {
    const std::string e0 = first[1371];
    Result moved = h.ReadText(ReplaceLine(
      first, 1372, "0 [3] : (0, 0, 0) x (0.0625, 0.0625, 0.07)    " + e0.substr(e0.find('{'))));
    ExpectError(status, moved, "moved corner", "overlaps", 0);
    // both elements are named, with their lines
    SV_CHECK(status, moved.Message.find("element 0") != std::string::npos);
    SV_CHECK(status, moved.Message.find("line 1372") != std::string::npos);
    ExpectError(status,
      h.ReadText(ReplaceLine(first, 1372, e0.substr(0, e0.find('{')) + "{0, 1, 2, 3}")),
      "short support list", "element 0 lists 4 basis functions", 1372);
    ExpectError(status,
      h.ReadText(ReplaceLine(first, 1372, e0.substr(0, e0.find('{')) + "{0, 1, 2 3}")),
      "malformed support list", "expected ',' or '}'", 1372);
    ExpectError(status,
      h.ReadText(ReplaceLine(first, 1372, e0.substr(0, e0.find('{')) + "{0, 1, 5000}")),
      "support index out of range", "out of range", 1372);
    ExpectError(status,
      h.ReadText(ReplaceLine(first, 22,
        "17: [0 0 0.03 0.0625 ] x [0 0 0.0625 0.125 ] x [0 0.0625 0.125 0.1875 ] 0 0 0 (1)")),
      "knots not on the mesh", "basis function 17 on line 22", 0);
  }

  // g2.
  {
    const std::string g2 =
      lrtest::ReadText(std::string(SPLINEVIZ_EXTERNAL_DATA_DIR) + "/tensor-product-volume.g2");
    const std::vector<std::string> g = SplitLines(g2);
    Result ok = h.ReadText(g2, ".g2");
    SV_CHECK_MSG(status, ok.Ok, ok.Message);
    ExpectError(status,
      h.ReadText(JoinLines(std::vector<std::string>(g.begin(), g.end() - 5)), ".g2"),
      "g2 truncated", "truncated", static_cast<int>(g.size()) - 5);
    ExpectError(status, h.ReadText(ReplaceLine(g, 1, "701 1 0 4 0 0 255 255"), ".g2"), "g2 class",
      "class 701", 1);
    ExpectError(status, h.ReadText(ReplaceLine(g, 1, "100 1 0 4 0 0 255 255"), ".g2"), "g2 curve",
      "curve", 1);
    ExpectError(status, h.ReadText(ReplaceLine(g, 20, "nan -1.17303638042237 0"), ".g2"), "g2 NaN",
      "not a finite number", 20);
    // Rational with the third coordinate as weight: zero weights on its first coefficients.
    ExpectError(status, h.ReadText(ReplaceLine(g, 4, "2 1"), ".g2"), "g2 rational, zero weight",
      "weight", 11);
    ExpectError(
      status, h.ReadText(ReplaceLine(g, 6, "0 0 0 1 1 1 1"), ".g2"), "g2 short knot vector", "", 0);
    ExpectError(status, h.ReadText(ReplaceLine(g, 6, "0 0 0.5 0 1 1 1 1"), ".g2"),
      "g2 decreasing knots", "non-decreasing", 6);
    ExpectError(status, h.ReadText(ReplaceLine(g, 6, "0 0.1 0.2 0.3 1 1 1 1"), ".g2"),
      "g2 unclamped", "clamped", 6);
  }

  // Fuzz: random mutations of the first patch. Every read must end (quickly)
  // with either valid finite output or a failure with a message.
  {
    std::mt19937 rng(2024);
    const std::string alphabet = "[](),:{}x#-.e0123456789 \n\tnaif";
    const char* tokens[] = { "nan", "-1", "0", "1e308", "-0", "99999999", "inf", "]", "[", "x", "(",
      ")", "{", "}", ",", ":", "# LRSPLINE VOLUME", "1e-300", "3", "0.0625" };
    int succeeded = 0, failed = 0;
    double slowest = 0.0;
    const int iterations = 300;
    for (int it = 0; it < iterations; ++it)
    {
      std::string text = firstText;
      const int numMutations = 1 + static_cast<int>(rng() % 3);
      for (int m = 0; m < numMutations; ++m)
      {
        const std::size_t pos = rng() % text.size();
        switch (rng() % 8)
        {
          case 0: // delete a range
            text.erase(pos, 1 + rng() % 40);
            break;
          case 1: // insert random characters
          {
            std::string ins;
            for (unsigned k = 0; k < 1 + rng() % 6; ++k)
            {
              ins += alphabet[rng() % alphabet.size()];
            }
            text.insert(pos, ins);
            break;
          }
          case 2: // replace a token
          {
            std::size_t b = text.find_last_of(" \t\n[](),:{}", pos);
            b = b == std::string::npos ? 0 : b + 1;
            std::size_t e = text.find_first_of(" \t\n[](),:{}", pos);
            e = e == std::string::npos ? text.size() : e;
            text.replace(
              b, e > b ? e - b : 0, tokens[rng() % (sizeof(tokens) / sizeof(tokens[0]))]);
            break;
          }
          case 3: // flip a digit
            if (std::isdigit(static_cast<unsigned char>(text[pos])))
            {
              text[pos] = static_cast<char>('0' + rng() % 10);
            }
            break;
          case 4: // truncate
            text.resize(pos);
            break;
          default: // duplicate, delete or swap lines
          {
            std::vector<std::string> ls = SplitLines(text);
            if (ls.size() < 3)
            {
              break;
            }
            const std::size_t a = rng() % ls.size(), b = rng() % ls.size();
            const int kind = static_cast<int>(rng() % 3);
            if (kind == 0)
            {
              ls.insert(ls.begin() + a, ls[b]);
            }
            else if (kind == 1)
            {
              ls.erase(ls.begin() + a);
            }
            else
            {
              std::swap(ls[a], ls[b]);
            }
            text = JoinLines(ls);
          }
        }
        if (text.empty())
        {
          text = "#";
        }
      }
      const auto t0 = std::chrono::steady_clock::now();
      Result r = h.ReadText(text);
      const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      slowest = std::max(slowest, seconds);
      if (r.Ok)
      {
        ++succeeded;
        bool finite = r.Output->GetNumberOfBlocks() >= 1;
        for (unsigned int b = 0; b < r.Output->GetNumberOfBlocks(); ++b)
        {
          auto* grid = vtkUnstructuredGrid::SafeDownCast(r.Output->GetBlock(b));
          if (!grid || grid->GetNumberOfCells() < 1)
          {
            finite = false;
            continue;
          }
          double bounds[6];
          grid->GetBounds(bounds);
          vtkDataArray* field = grid->GetPointData()->GetArray("Field");
          double range[2] = { 0, 0 };
          if (field)
          {
            field->GetRange(range, -1);
          }
          for (double v : bounds)
          {
            finite = finite && std::isfinite(v);
          }
          finite = finite && field && std::isfinite(range[0]) && std::isfinite(range[1]);
        }
        SV_CHECK_MSG(
          status, finite, "fuzz " << it << ": a successful read with non-finite or empty output");
      }
      else
      {
        ++failed;
        SV_CHECK_MSG(status, r.Message.find("line ") != std::string::npos,
          "fuzz " << it << ": failure without a line: " << r.Message);
      }
    }
    std::cout << "fuzz: " << iterations << " mutated files, " << succeeded << " read, " << failed
              << " rejected with a message; slowest read " << slowest << " s" << std::endl;
    SV_CHECK(status, failed > iterations / 3);
    SV_CHECK(status, slowest < 10.0);
  }
  return status.Result();
}
