// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIFEMLagrangePatch.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkHigherOrderHexahedron.h"
#include "vtkHigherOrderQuadrilateral.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <unordered_map>

namespace
{
// Lines of a text, with their numbers, without allocating per line.
class LineReader
{
public:
  explicit LineReader(const std::string& text)
    : P(text.data())
    , E(text.data() + text.size())
  {
  }
  bool Next(const char*& begin, const char*& end)
  {
    if (this->P >= this->E)
    {
      return false;
    }
    begin = this->P;
    while (this->P < this->E && *this->P != '\n')
    {
      ++this->P;
    }
    end = this->P;
    if (this->P < this->E)
    {
      ++this->P;
    }
    ++this->Line;
    return true;
  }
  int Line = 0;

private:
  const char* P;
  const char* E;
};

// The numbers of one line (strtod / strtoll on a bounded copy).
bool Numbers(const char* begin, const char* end, std::vector<double>& out)
{
  out.clear();
  std::string line(begin, end);
  const char* p = line.c_str();
  for (;;)
  {
    while (*p == ' ' || *p == '\t' || *p == '\r')
    {
      ++p;
    }
    if (!*p)
    {
      return true;
    }
    char* stop = nullptr;
    errno = 0;
    const double v = std::strtod(p, &stop);
    if (stop == p)
    {
      return false;
    }
    out.push_back(v);
    p = stop;
  }
}

bool Fail(std::string* error, int line, const std::string& message)
{
  if (error)
  {
    *error = "line " + std::to_string(line) + ": " + message;
  }
  return false;
}

// Value of "key=value" in the header, or -1.
long long HeaderCount(const std::string& header, const std::string& key)
{
  const std::size_t at = header.find(key + "=");
  if (at == std::string::npos)
  {
    return -1;
  }
  const char* p = header.c_str() + at + key.size() + 1;
  char* stop = nullptr;
  const long long v = std::strtoll(p, &stop, 10);
  return stop == p ? -1 : v;
}
}

//------------------------------------------------------------------------------
bool vtkIFEMLagrangePatch::Parse(const std::string& text, std::string* error)
{
  this->Nodes.clear();
  this->Elements.clear();
  LineReader lines(text);
  const char* b = nullptr;
  const char* e = nullptr;
  if (!lines.Next(b, e) || std::string(b, e).compare(0, 12, "# LAGRANGIAN") != 0)
  {
    return Fail(error, 1, "expected the header \"# LAGRANGIAN nodes=N elements=M type=T\"");
  }
  const std::string header(b, e);
  const long long nn = HeaderCount(header, "nodes");
  const long long ne = HeaderCount(header, "elements");
  const std::size_t typeAt = header.find("type=");
  this->TypeName = typeAt == std::string::npos ? "" : header.substr(typeAt + 5);
  while (!this->TypeName.empty() && std::isspace(static_cast<unsigned char>(this->TypeName.back())))
  {
    this->TypeName.pop_back();
  }
  // Each node needs at least 6 characters ("0 0 0\n"), each element 2 per node.
  if (nn < 1 || ne < 1 || static_cast<double>(nn) * 6 > static_cast<double>(text.size()) ||
    static_cast<double>(ne) * 2 > static_cast<double>(text.size()))
  {
    return Fail(error, 1,
      "the numbers of nodes and elements (" + std::to_string(nn) + ", " + std::to_string(ne) +
        ") are missing, not positive or more than the text can hold");
  }
  if (this->TypeName == "hexahedron")
  {
    this->CellType = VTK_LAGRANGE_HEXAHEDRON;
    this->ParametricDimension = 3;
  }
  else if (this->TypeName == "quad")
  {
    this->CellType = VTK_LAGRANGE_QUADRILATERAL;
    this->ParametricDimension = 2;
  }
  else if (this->TypeName == "triangle")
  {
    this->CellType = VTK_TRIANGLE;
    this->ParametricDimension = 2;
  }
  else if (this->TypeName == "line")
  {
    this->CellType = VTK_LAGRANGE_CURVE;
    this->ParametricDimension = 1;
  }
  else
  {
    return Fail(error, 1,
      "unknown Lagrange element type \"" + this->TypeName +
        "\" (expected hexahedron, quad, triangle or line)");
  }
  std::vector<double> numbers;
  this->Nodes.reserve(static_cast<std::size_t>(nn) * 3);
  for (long long i = 0; i < nn; ++i)
  {
    if (!lines.Next(b, e))
    {
      return Fail(error, lines.Line, "the text ends before node " + std::to_string(i));
    }
    if (!Numbers(b, e, numbers) || numbers.size() != 3)
    {
      return Fail(error, lines.Line, "a node needs 3 coordinates");
    }
    for (double v : numbers)
    {
      if (!std::isfinite(v))
      {
        return Fail(error, lines.Line, "a coordinate is not a finite number");
      }
      this->Nodes.push_back(v);
    }
  }
  for (long long c = 0; c < ne; ++c)
  {
    if (!lines.Next(b, e))
    {
      return Fail(error, lines.Line, "the text ends before element " + std::to_string(c));
    }
    if (!Numbers(b, e, numbers) || numbers.empty())
    {
      return Fail(error, lines.Line, "an element needs its node numbers");
    }
    if (c == 0)
    {
      this->NodesPerElement = static_cast<int>(numbers.size());
      const double n = static_cast<double>(numbers.size());
      const int root = static_cast<int>(std::lround(this->ParametricDimension == 3
          ? std::cbrt(n)
          : (this->ParametricDimension == 2 ? std::sqrt(n) : n)));
      const int expected = this->ParametricDimension == 3
        ? root * root * root
        : (this->ParametricDimension == 2 ? root * root : root);
      this->Degree = root - 1;
      const bool ok = this->CellType == VTK_TRIANGLE
        ? numbers.size() == 3
        : (expected == static_cast<int>(numbers.size()) && root >= 2 && root <= 11);
      if (!ok)
      {
        return Fail(error, lines.Line,
          "a " + this->TypeName + " with " + std::to_string(numbers.size()) +
            " nodes is not supported (a tensor grid of (p+1)^d nodes, p from 1 to 10; 3 for a "
            "triangle)");
      }
      this->Degree = this->CellType == VTK_TRIANGLE ? 1 : this->Degree;
      this->Elements.reserve(static_cast<std::size_t>(ne) * numbers.size());
    }
    if (static_cast<int>(numbers.size()) != this->NodesPerElement)
    {
      return Fail(error, lines.Line, "all elements must have the same number of nodes");
    }
    for (double v : numbers)
    {
      if (!(v >= 0 && v < static_cast<double>(nn)) || v != std::floor(v))
      {
        return Fail(
          error, lines.Line, "a node number is not one of 0 to " + std::to_string(nn - 1));
      }
      this->Elements.push_back(static_cast<vtkIdType>(v));
    }
  }
  return true;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkUnstructuredGrid> vtkIFEMLagrangePatch::BuildGrid(vtkIdType first,
  vtkIdType last, std::vector<vtkIdType>& nodeIds, std::vector<vtkIdType>& elementIds) const
{
  const int npe = this->NodesPerElement;
  const int p = this->Degree;
  const int order[3] = { p, p, p };
  std::unordered_map<vtkIdType, vtkIdType> pointOf;
  nodeIds.clear();
  elementIds.clear();
  vtkNew<vtkIdTypeArray> offsets, connectivity;
  offsets->SetNumberOfTuples(last - first + 1);
  connectivity->SetNumberOfTuples((last - first) * npe);
  for (vtkIdType c = first; c < last; ++c)
  {
    offsets->SetValue(c - first, (c - first) * npe);
    elementIds.push_back(c);
    for (int k = 0; k < npe; ++k)
    {
      const vtkIdType node = this->Elements[static_cast<std::size_t>(c) * npe + k];
      auto it = pointOf.find(node);
      vtkIdType id;
      if (it == pointOf.end())
      {
        id = static_cast<vtkIdType>(nodeIds.size());
        pointOf[node] = id;
        nodeIds.push_back(node);
      }
      else
      {
        id = it->second;
      }
      // IFEM numbers a tensor element's nodes with the first direction fastest.
      int local = k;
      if (this->CellType == VTK_LAGRANGE_HEXAHEDRON)
      {
        local = vtkHigherOrderHexahedron::PointIndexFromIJK(
          k % (p + 1), (k / (p + 1)) % (p + 1), k / ((p + 1) * (p + 1)), order);
      }
      else if (this->CellType == VTK_LAGRANGE_QUADRILATERAL)
      {
        local = vtkHigherOrderQuadrilateral::PointIndexFromIJK(k % (p + 1), k / (p + 1), order);
      }
      else if (this->CellType == VTK_LAGRANGE_CURVE)
      {
        local = k == 0 ? 0 : (k == p ? 1 : k + 1);
      }
      connectivity->SetValue((c - first) * npe + local, id);
    }
  }
  offsets->SetValue(last - first, (last - first) * npe);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(nodeIds.size()));
  for (std::size_t i = 0; i < nodeIds.size(); ++i)
  {
    points->SetPoint(static_cast<vtkIdType>(i), this->Nodes.data() + 3 * nodeIds[i]);
  }
  vtkNew<vtkUnstructuredGrid> grid;
  grid->SetPoints(points);
  vtkNew<vtkCellArray> cells;
  cells->SetData(offsets, connectivity);
  grid->SetCells(this->CellType, cells);
  if (this->CellType != VTK_TRIANGLE)
  {
    vtkNew<vtkIntArray> degrees;
    degrees->SetName("HigherOrderDegrees");
    degrees->SetNumberOfComponents(3);
    degrees->SetNumberOfTuples(last - first);
    for (vtkIdType c = 0; c < last - first; ++c)
    {
      for (int d = 0; d < 3; ++d)
      {
        degrees->SetTypedComponent(c, d, d < this->ParametricDimension ? p : 0);
      }
    }
    grid->GetCellData()->AddArray(degrees);
    grid->GetCellData()->SetHigherOrderDegrees(degrees);
  }
  return vtkSmartPointer<vtkUnstructuredGrid>(grid.GetPointer());
}
