// SPDX-License-Identifier: BSD-3-Clause
// vtkTractogramReader and vtkTractogramWriter: round trips through .tck
// (+ .tsf) and .trk with point and cell arrays, the .trk voxel-mm bytes
// against the voxel-mm formula written out here, a .trk read and written back
// keeps its geometry, big-endian .tck, a .tck with an empty streamline (and
// its .tsf), a TrackVis version 1 file without scalars (empty voxel order =
// LPS) against the analytic map, pieces, 1 and 2 threads, progress per chunk
// and abort. Independent checks against nibabel are in
// Testing/Python/TestNeuroimagingNibabel.py.
#include "vtkTractogramReader.h"
#include "vtkTractogramWriter.h"

#include "NeuroimagingTestFiles.h"
#include "SplineVizTestUtilities.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkStringArray.h"

#include <cmath>
#include <cstdio>
#include <vector>

namespace
{
using namespace neurotest;

// Random polylines (float32 points), point arrays FA (1) and RGB (3), cell
// arrays Weight (1) and Bundle (2); one line has a single point.
vtkSmartPointer<vtkPolyData> RandomLines(int nLines, int seed)
{
  vtkNew<vtkMinimalStandardRandomSequence> rnd;
  rnd->SetSeed(seed);
  auto next = [&rnd](double lo, double hi)
  {
    rnd->Next();
    return rnd->GetRangeValue(lo, hi);
  };
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  vtkNew<vtkCellArray> cells;
  vtkNew<vtkFloatArray> fa, rgb, weight, bundle;
  fa->SetName("FA");
  rgb->SetName("RGB");
  rgb->SetNumberOfComponents(3);
  weight->SetName("Weight");
  bundle->SetName("Bundle");
  bundle->SetNumberOfComponents(2);
  for (int l = 0; l < nLines; ++l)
  {
    const int n = l == 3 ? 1 : 2 + static_cast<int>(next(0, 38));
    cells->InsertNextCell(n);
    double x[3] = { next(-80, 80), next(-100, 80), next(-60, 90) };
    for (int j = 0; j < n; ++j)
    {
      for (double& c : x)
      {
        c += next(-1.5, 1.5);
      }
      cells->InsertCellPoint(points->InsertNextPoint(x));
      fa->InsertNextValue(static_cast<float>(next(0, 1)));
      rgb->InsertNextTuple3(next(0, 1), next(0, 1), next(0, 1));
    }
    weight->InsertNextValue(static_cast<float>(next(0, 10)));
    bundle->InsertNextTuple2(l % 4, next(-1, 1));
  }
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  pd->SetPoints(points);
  pd->SetLines(cells);
  pd->GetPointData()->AddArray(fa);
  pd->GetPointData()->AddArray(rgb);
  pd->GetCellData()->AddArray(weight);
  pd->GetCellData()->AddArray(bundle);
  return pd;
}

// Largest difference between the lines (point by point) of a and b; -1 if
// their structure differs.
double LineDifference(vtkPolyData* a, vtkPolyData* b)
{
  if (a->GetNumberOfLines() != b->GetNumberOfLines())
  {
    return -1;
  }
  vtkNew<vtkIdList> ia, ib;
  double worst = 0;
  for (vtkIdType l = 0; l < a->GetNumberOfLines(); ++l)
  {
    a->GetLines()->GetCellAtId(l, ia);
    b->GetLines()->GetCellAtId(l, ib);
    if (ia->GetNumberOfIds() != ib->GetNumberOfIds())
    {
      return -1;
    }
    for (vtkIdType j = 0; j < ia->GetNumberOfIds(); ++j)
    {
      double p[3], q[3];
      a->GetPoint(ia->GetId(j), p);
      b->GetPoint(ib->GetId(j), q);
      for (int c = 0; c < 3; ++c)
      {
        worst = std::max(worst, std::abs(p[c] - q[c]));
      }
    }
  }
  return worst;
}

// Largest difference of a point (or cell) array along the lines of a and b.
double ArrayDifference(vtkPolyData* a, vtkPolyData* b, const char* name, bool cell)
{
  vtkDataArray* x = cell ? a->GetCellData()->GetArray(name) : a->GetPointData()->GetArray(name);
  vtkDataArray* y = cell ? b->GetCellData()->GetArray(name) : b->GetPointData()->GetArray(name);
  if (!x || !y || x->GetNumberOfComponents() != y->GetNumberOfComponents())
  {
    return -1;
  }
  double worst = 0;
  if (cell)
  {
    for (vtkIdType l = 0; l < a->GetNumberOfLines(); ++l)
    {
      for (int c = 0; c < x->GetNumberOfComponents(); ++c)
      {
        worst = std::max(worst, std::abs(x->GetComponent(l, c) - y->GetComponent(l, c)));
      }
    }
    return worst;
  }
  vtkNew<vtkIdList> ia, ib;
  for (vtkIdType l = 0; l < a->GetNumberOfLines(); ++l)
  {
    a->GetLines()->GetCellAtId(l, ia);
    b->GetLines()->GetCellAtId(l, ib);
    for (vtkIdType j = 0; j < ia->GetNumberOfIds(); ++j)
    {
      for (int c = 0; c < x->GetNumberOfComponents(); ++c)
      {
        worst = std::max(
          worst, std::abs(x->GetComponent(ia->GetId(j), c) - y->GetComponent(ib->GetId(j), c)));
      }
    }
  }
  return worst;
}

vtkSmartPointer<vtkPolyData> Read(Harness& h, vtkTractogramReader* r, bool& ok)
{
  ok = h.Run(r);
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->DeepCopy(r->GetOutput());
  return copy;
}

float FloatAt(const std::string& bytes, std::size_t offset)
{
  float f;
  std::memcpy(&f, bytes.data() + offset, 4);
  return f; // the test host is little-endian (checked below)
}
}

int TestTractogramIO(int, char*[])
{
  SplineVizTestStatus status;
  Harness h;
  SV_CHECK(status, HostLittleEndian());
  auto lines = RandomLines(60, 7);

  //----------------------------------------------------------------------------
  // .tck + .tsf round trip.
  {
    const std::string tck = OutDir + "/TestTractogramIO.tck";
    vtkNew<vtkTractogramWriter> w;
    h.Watch(w);
    w->SetInputData(lines);
    w->SetFileName(tck.c_str());
    w->AddPointArrayName("FA");
    SV_CHECK_MSG(status, h.Run(w), h.Error());
    const std::string tsf = vtkTractogramWriter::ScalarFileName(tck, "FA");
    SV_CHECK(status, tsf == OutDir + "/TestTractogramIO.FA.tsf");
    vtkNew<vtkTractogramReader> r;
    h.Watch(r);
    r->SetFileName(tck.c_str());
    r->AddScalarFileName(tsf.c_str());
    bool ok;
    auto back = Read(h, r, ok);
    SV_CHECK_MSG(status, ok, h.Error());
    SV_CHECK(status, vtkTractogramReader::ScalarArrayName(tsf, tck) == "FA");
    SV_CHECK_NEAR(status, LineDifference(lines, back), 0.0, 0.0); // float32 both ways: exact
    SV_CHECK_NEAR(status, ArrayDifference(lines, back, "FA", false), 0.0, 0.0);
    SV_CHECK(status, r->GetNumberOfStreamlinesInFile() == 60);
    auto* header =
      vtkStringArray::SafeDownCast(back->GetFieldData()->GetAbstractArray("MRtrixHeader"));
    bool stamped = false;
    for (vtkIdType i = 0; header && i < header->GetNumberOfValues(); ++i)
    {
      stamped = stamped || header->GetValue(i).rfind("timestamp: ", 0) == 0;
    }
    SV_CHECK(status, stamped);
    // The file's own structure, read byte by byte: count, NaN separators, inf end.
    const std::string bytes = ReadBytes(tck);
    SV_CHECK(status, bytes.rfind("mrtrix tracks\n", 0) == 0);
    SV_CHECK(status, bytes.find("count: 0000000060\n") != std::string::npos);
    SV_CHECK(status, bytes.find("datatype: Float32LE\n") != std::string::npos);
    const std::size_t fileKey = bytes.find("file: . ");
    const std::size_t offset = std::stoul(bytes.substr(fileKey + 8));
    SV_CHECK(status, bytes.compare(offset - 4, 4, "END\n") == 0);
    const std::size_t nValues = (bytes.size() - offset) / 4;
    SV_CHECK(status, nValues == 3 * (lines->GetNumberOfPoints() + 60 + 1));
    SV_CHECK(status, std::isinf(FloatAt(bytes, bytes.size() - 4)));
    SV_CHECK(status, std::isnan(FloatAt(bytes, bytes.size() - 16)));
    double first[3];
    lines->GetPoint(0, first);
    SV_CHECK(status, FloatAt(bytes, offset) == static_cast<float>(first[0]));
    // a second array that cannot go to a .tsf: 3 components
    w->AddPointArrayName("RGB");
    SV_CHECK(status, !h.Run(w));
    SV_CHECK(status, h.Error().find("one value per point") != std::string::npos);
  }

  //----------------------------------------------------------------------------
  // .trk round trip with a rotated, flipped voxel grid, scalars and properties.
  {
    vtkNew<vtkImageData> grid;
    grid->SetDimensions(90, 108, 90);
    grid->SetSpacing(2.0, 2.5, 1.5);
    grid->SetOrigin(91.0, -126.0, -72.0);
    double axis[3] = { 1, 2, 3 };
    vtkMath::Normalize(axis);
    double q[4] = { std::cos(0.25), std::sin(0.25) * axis[0], std::sin(0.25) * axis[1],
      std::sin(0.25) * axis[2] };
    double r[3][3];
    vtkMath::QuaternionToMatrix3x3(q, r);
    double d[9];
    for (int i = 0; i < 3; ++i)
    {
      d[3 * i + 0] = -r[i][0]; // a flip of the first axis (LAS-like)
      d[3 * i + 1] = r[i][1];
      d[3 * i + 2] = r[i][2];
    }
    grid->SetDirectionMatrix(d);
    const std::string trk = OutDir + "/TestTractogramIO.trk";
    vtkNew<vtkTractogramWriter> w;
    h.Watch(w);
    w->SetInputData(lines);
    w->SetFileName(trk.c_str());
    w->SetGeometryFromImage(grid);
    w->AddPointArrayName("FA");
    w->AddPointArrayName("RGB");
    w->AddCellArrayName("Weight");
    w->AddCellArrayName("Bundle");
    SV_CHECK_MSG(status, h.Run(w), h.Error());
    vtkNew<vtkTractogramReader> rd;
    h.Watch(rd);
    rd->SetFileName(trk.c_str());
    bool ok;
    auto back = Read(h, rd, ok);
    SV_CHECK_MSG(status, ok, h.Error());
    const double pointError = LineDifference(lines, back);
    std::cout << ".trk round trip: largest point difference " << pointError << " mm" << std::endl;
    SV_CHECK(status, pointError >= 0 && pointError < 1e-4);
    SV_CHECK_NEAR(status, ArrayDifference(lines, back, "FA", false), 0.0, 0.0);
    SV_CHECK_NEAR(status, ArrayDifference(lines, back, "RGB", false), 0.0, 0.0);
    SV_CHECK_NEAR(status, ArrayDifference(lines, back, "Weight", true), 0.0, 0.0);
    SV_CHECK_NEAR(status, ArrayDifference(lines, back, "Bundle", true), 0.0, 0.0);
    // The first point's bytes are TrackVis voxel mm: (A^-1 x + 1/2) * voxel size.
    const std::string bytes = ReadBytes(trk);
    SV_CHECK(status, bytes.size() > 1000 && bytes.compare(0, 6, std::string("TRACK\0", 6)) == 0);
    SV_CHECK(
      status, bytes.compare(948, 4, std::string("LAS\0", 4)) == 0); // axis codes of vox_to_ras
    double x[3], u[3];
    lines->GetPoint(0, x);
    double rel[3] = { x[0] - 91.0, x[1] + 126.0, x[2] + 72.0 };
    const double spacing[3] = { 2.0, 2.5, 1.5 };
    for (int j = 0; j < 3; ++j) // D is orthogonal: D^-1 = D^T
    {
      const double idx = (d[j] * rel[0] + d[3 + j] * rel[1] + d[6 + j] * rel[2]) / spacing[j];
      u[j] = (idx + 0.5) * spacing[j];
    }
    for (int c = 0; c < 3; ++c)
    {
      SV_CHECK_NEAR(status, FloatAt(bytes, 1004 + 4 * c), u[c], 1e-4);
    }
    // read and written back: the same header geometry
    const std::string again = OutDir + "/TestTractogramIO-again.trk";
    vtkNew<vtkTractogramWriter> w2;
    h.Watch(w2);
    w2->SetInputData(back);
    w2->SetFileName(again.c_str());
    SV_CHECK_MSG(status, h.Run(w2), h.Error());
    const std::string bytes2 = ReadBytes(again);
    SV_CHECK(status, bytes2.compare(6, 6 + 12, bytes, 6, 6 + 12) == 0); // dim, voxel size
    SV_CHECK(status, bytes2.compare(440, 64, bytes, 440, 64) == 0);     // vox_to_ras
    SV_CHECK(status, bytes2.compare(948, 4, bytes, 948, 4) == 0);       // voxel order
    rd->SetFileName(again.c_str());
    auto back2 = Read(h, rd, ok);
    SV_CHECK(status, ok && LineDifference(back, back2) < 1e-4);
  }

  //----------------------------------------------------------------------------
  // Big-endian .tck, and an empty streamline (with a matching .tsf).
  {
    const std::vector<std::vector<float>> raw = { { 1.5f, -2.0f, 3.25f, 4.0f, 5.0f, -6.5f }, {},
      { 7.0f, 8.0f, 9.0f } };
    const std::string be = OutDir + "/TestTractogramIO-be.tck";
    WriteBytes(be, MRtrixBytes("mrtrix tracks", "count: 3\n", TckValues(raw), true));
    vtkNew<vtkTractogramReader> r;
    h.Watch(r);
    r->SetFileName(be.c_str());
    bool ok;
    auto out = Read(h, r, ok);
    SV_CHECK_MSG(status, ok, h.Error());
    SV_CHECK(status, out->GetNumberOfLines() == 2 && out->GetNumberOfPoints() == 3);
    SV_CHECK(status, r->GetNumberOfStreamlinesInFile() == 3);
    double p[3];
    out->GetPoint(1, p);
    SV_CHECK(status, p[0] == 4.0 && p[1] == 5.0 && p[2] == -6.5);
    out->GetPoint(2, p);
    SV_CHECK(status, p[0] == 7.0 && p[1] == 8.0 && p[2] == 9.0);
    // negative control: the same bytes declared little-endian are other numbers
    const std::string wrong = OutDir + "/TestTractogramIO-be-as-le.tck";
    std::string bytes = ReadBytes(be);
    bytes.replace(bytes.find("Float32BE"), 9, "Float32LE");
    WriteBytes(wrong, bytes);
    r->SetFileName(wrong.c_str());
    auto garbled = Read(h, r, ok);
    SV_CHECK(status, !ok || LineDifference(out, garbled) != 0.0);

    // keep the empty streamline: cell 1 has no points, FA from the .tsf aligned
    const std::string le = OutDir + "/TestTractogramIO-empty.tck";
    WriteBytes(le, MRtrixBytes("mrtrix tracks", "count: 3\ntimestamp: 42\n", TckValues(raw)));
    const std::string tsf = OutDir + "/TestTractogramIO-empty_FA.tsf";
    // one value per point, a NaN after each streamline, inf at the end
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    WriteBytes(tsf,
      MRtrixBytes(
        "mrtrix track scalars", "timestamp: 42\n", { 0.1f, 0.2f, nan, nan, 0.3f, nan, inf }));
    r->SetFileName(le.c_str());
    r->AddScalarFileName(tsf.c_str());
    r->KeepEmptyStreamlinesOn();
    auto kept = Read(h, r, ok);
    SV_CHECK_MSG(status, ok, h.Error());
    SV_CHECK(status, kept->GetNumberOfLines() == 3 && kept->GetNumberOfPoints() == 3);
    vtkNew<vtkIdList> ids;
    kept->GetLines()->GetCellAtId(1, ids);
    SV_CHECK(status, ids->GetNumberOfIds() == 0);
    vtkDataArray* fa = kept->GetPointData()->GetArray("FA");
    SV_CHECK(status, fa && std::abs(fa->GetComponent(2, 0) - 0.3) < 1e-7);
    r->KeepEmptyStreamlinesOff();
    auto dropped = Read(h, r, ok);
    SV_CHECK(status, ok && dropped->GetNumberOfLines() == 2);
    fa = dropped->GetPointData()->GetArray("FA");
    SV_CHECK(status, fa && std::abs(fa->GetComponent(1, 0) - 0.2) < 1e-7);
    // a .tsf with another structure is refused
    WriteBytes(tsf, MRtrixBytes("mrtrix track scalars", "", { 0.1f, 0.2f, nan, 0.3f, nan, inf }));
    auto refused = Read(h, r, ok);
    SV_CHECK(status, !ok && refused->GetNumberOfPoints() == 0);
    SV_CHECK(status, h.Error().find("does not match") != std::string::npos);
  }

  //----------------------------------------------------------------------------
  // TrackVis version 1 without scalars: identity vox_to_ras, empty voxel order
  // = LPS: x = (dim_x - 1) - (X / vs_x - 1/2), y likewise, z = Z / vs_z - 1/2.
  {
    TrkFile t;
    t.Version = 1;
    t.VoxelOrder = "";
    t.Dim[0] = 10;
    t.Dim[1] = 20;
    t.Dim[2] = 30;
    t.VoxelSize[0] = 2;
    t.VoxelSize[1] = 3;
    t.VoxelSize[2] = 4;
    t.Count = 2;
    t.AddStreamline(2, { 1, 1.5, 2, 10, 12, 14 }, {});
    t.AddStreamline(1, { 19, 58, 118 }, {});
    const std::string path = OutDir + "/TestTractogramIO-v1.trk";
    WriteBytes(path, t.Bytes());
    vtkNew<vtkTractogramReader> r;
    h.Watch(r);
    r->SetFileName(path.c_str());
    bool ok;
    auto out = Read(h, r, ok);
    SV_CHECK_MSG(status, ok, h.Error());
    SV_CHECK(status, out->GetNumberOfLines() == 2 && out->GetNumberOfPoints() == 3);
    SV_CHECK(status, out->GetPointData()->GetNumberOfArrays() == 0);
    const double voxmm[3][3] = { { 1, 1.5, 2 }, { 10, 12, 14 }, { 19, 58, 118 } };
    for (int i = 0; i < 3; ++i)
    {
      double p[3];
      out->GetPoint(i, p);
      SV_CHECK_NEAR(status, p[0], 9.0 - (voxmm[i][0] / 2 - 0.5), 1e-5);
      SV_CHECK_NEAR(status, p[1], 19.0 - (voxmm[i][1] / 3 - 0.5), 1e-5);
      SV_CHECK_NEAR(status, p[2], voxmm[i][2] / 4 - 0.5, 1e-5);
    }
    // big-endian version of the same file: the same points
    t.BigEndian = true;
    t.Records.clear();
    t.AddStreamline(2, { 1, 1.5, 2, 10, 12, 14 }, {});
    t.AddStreamline(1, { 19, 58, 118 }, {});
    WriteBytes(path, t.Bytes());
    auto be = Read(h, r, ok);
    SV_CHECK_MSG(status, ok && LineDifference(out, be) == 0.0, h.Error());
  }

  //----------------------------------------------------------------------------
  // Pieces, threads, progress per chunk, abort (a 3 M-point .tck: 3 reads of
  // 16 MiB and 2 parallel batches).
  {
    const std::string big = OutDir + "/TestTractogramIO-big.tck";
    {
      vtkNew<vtkPoints> pts;
      pts->SetDataTypeToFloat();
      vtkNew<vtkCellArray> cells;
      const int n = 30000, m = 100;
      pts->SetNumberOfPoints(vtkIdType(n) * m);
      for (int l = 0; l < n; ++l)
      {
        cells->InsertNextCell(m);
        for (int j = 0; j < m; ++j)
        {
          const vtkIdType id = vtkIdType(l) * m + j;
          pts->SetPoint(id, std::cos(0.001 * l) * j, std::sin(0.002 * l) * j, 0.01 * l);
          cells->InsertCellPoint(id);
        }
      }
      vtkNew<vtkPolyData> pd;
      pd->SetPoints(pts);
      pd->SetLines(cells);
      vtkNew<vtkTractogramWriter> w;
      w->SetInputData(pd);
      w->SetFileName(big.c_str());
      w->Write();
    }
    vtkNew<vtkTractogramReader> r;
    h.Watch(r);
    r->SetFileName(big.c_str());
    int progressEvents = 0;
    vtkNew<vtkCallbackCommand> count;
    count->SetClientData(&progressEvents);
    count->SetCallback(
      [](vtkObject*, unsigned long, void* cd, void*) { ++*static_cast<int*>(cd); });
    r->AddObserver(vtkCommand::ProgressEvent, count);
    vtkSMPTools::Initialize(2);
    bool ok;
    auto two = Read(h, r, ok);
    SV_CHECK_MSG(status, ok && two->GetNumberOfPoints() == 3000000, h.Error());
    std::cout << "3 M points: " << progressEvents << " progress events" << std::endl;
    SV_CHECK(status, progressEvents >= 5);
    vtkSMPTools::Initialize(1);
    auto one = Read(h, r, ok);
    SV_CHECK(status, ok && LineDifference(one, two) == 0.0);
    vtkSMPTools::Initialize(0);
    // three pieces make the whole
    vtkIdType linesSoFar = 0, pointsSoFar = 0;
    double worst = 0;
    for (int piece = 0; piece < 3; ++piece)
    {
      r->UpdatePiece(piece, 3, 0);
      vtkPolyData* part = r->GetOutput();
      vtkNew<vtkIdList> ia, ib;
      for (vtkIdType l = 0; l < part->GetNumberOfLines(); ++l)
      {
        part->GetLines()->GetCellAtId(l, ia);
        two->GetLines()->GetCellAtId(linesSoFar + l, ib);
        double p[3], q[3];
        part->GetPoint(ia->GetId(ia->GetNumberOfIds() - 1), p);
        two->GetPoint(ib->GetId(ib->GetNumberOfIds() - 1), q);
        worst =
          std::max(worst, std::abs(p[0] - q[0]) + std::abs(p[1] - q[1]) + std::abs(p[2] - q[2]));
      }
      linesSoFar += part->GetNumberOfLines();
      pointsSoFar += part->GetNumberOfPoints();
    }
    SV_CHECK(status, linesSoFar == 30000 && pointsSoFar == 3000000 && worst == 0.0);
    // abort from a progress observer: an empty output, no error; then a full read again
    vtkNew<vtkCallbackCommand> abort;
    abort->SetCallback([](vtkObject* caller, unsigned long, void*, void*)
      { static_cast<vtkAlgorithm*>(caller)->AbortExecuteOn(); });
    const unsigned long tag = r->AddObserver(vtkCommand::ProgressEvent, abort);
    r->UpdatePiece(0, 1, 0);
    auto aborted = Read(h, r, ok);
    SV_CHECK(status, aborted->GetNumberOfPoints() == 0);
    r->RemoveObserver(tag);
    r->AbortExecuteOff();
    auto again = Read(h, r, ok);
    SV_CHECK(status, ok && again->GetNumberOfPoints() == 3000000);
    std::remove(big.c_str());
  }

  //----------------------------------------------------------------------------
  // Composite input: the lines of every polydata block, in order.
  {
    vtkNew<vtkMultiBlockDataSet> mb;
    mb->SetBlock(0, RandomLines(5, 1));
    mb->SetBlock(1, RandomLines(7, 2));
    const std::string path = OutDir + "/TestTractogramIO-blocks.tck";
    vtkNew<vtkTractogramWriter> w;
    h.Watch(w);
    w->SetInputData(mb);
    w->SetFileName(path.c_str());
    SV_CHECK_MSG(status, h.Run(w), h.Error());
    vtkNew<vtkTractogramReader> r;
    h.Watch(r);
    r->SetFileName(path.c_str());
    bool ok;
    auto out = Read(h, r, ok);
    SV_CHECK(status, ok && out->GetNumberOfLines() == 12);
  }
  return status.Result();
}
