// SPDX-License-Identifier: BSD-3-Clause
// vtkTractogramReader and vtkTractogramWriter on bad input: every case must
// fail with a clear message (RequestData returns 0, an error is reported)
// and leave an empty output, never crash, hang or fill part of the output.
// .tck: truncated (no end marker, cut inside a triplet), wrong magic, no END,
// an unsupported datatype, a multi-file header, an offset past the end,
// triplets mixing NaN/inf with numbers, a streamline not ended before the
// end marker. .trk: wrong magic, wrong hdr_size, unknown version, a header
// count exceeding the file (refused before anything is allocated), a record
// running past the end, a negative point count, NaN coordinates, names
// covering more values than n_scalars, a file shorter than its header.
// Writer: NaN coordinates (the file is removed), a missing array, an unknown
// extension, too many TrackVis names. Plus a non-existent and an empty file,
// and sparse .tck and .trk files of four times this machine's memory (refused
// before anything is allocated).
#include "vtkTractogramReader.h"
#include "vtkTractogramWriter.h"

#include "NeuroimagingTestFiles.h"
#include "SplineVizTestUtilities.h"

#include "vtkCellArray.h"
#include "vtkFloatArray.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <vtksys/SystemInformation.hxx>

#include <chrono>
#include <cstdio>

namespace
{
using namespace neurotest;

struct Case
{
  std::string Name;
  std::string Bytes;
  std::string Extension;
  std::string Expected; // part of the error message
};
}

int TestTractogramBadInput(int, char*[])
{
  SplineVizTestStatus status;
  Harness h;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  const std::vector<std::vector<float>> two = { { 1, 2, 3, 4, 5, 6 }, { 7, 8, 9 } };
  const std::string good = MRtrixBytes("mrtrix tracks", "count: 2\n", TckValues(two));

  std::vector<Case> cases;
  cases.push_back(
    { "tck without end marker", good.substr(0, good.size() - 12), ".tck", "truncated" });
  cases.push_back(
    { "tck cut inside a triplet", good.substr(0, good.size() - 14), ".tck", "truncated" });
  cases.push_back({ "tck wrong magic", "mrtrix trucks\n" + good.substr(14), ".tck", "first line" });
  {
    std::string s = good;
    s.replace(s.find("END\n"), 4, "ENX\n");
    cases.push_back({ "tck without END", s, ".tck", "END" });
  }
  cases.push_back({ "tck Float16",
    MRtrixBytes("mrtrix tracks", "", TckValues(two), false, "Float16LE"), ".tck", "datatype" });
  {
    std::string s = good;
    s.replace(s.find("file: . "), 8, "file: x ");
    cases.push_back({ "tck multi-file", s, ".tck", "single-file" });
  }
  {
    std::string s = good;
    const std::size_t at = s.find("file: . ") + 8;
    s.replace(at, 8, "99999999");
    cases.push_back({ "tck offset past the end", s, ".tck", "outside the file" });
  }
  cases.push_back({ "tck mixed NaN triplet",
    MRtrixBytes("mrtrix tracks", "", { 1, 2, 3, nan, 5, 6, nan, nan, nan, inf, inf, inf }), ".tck",
    "mixes NaN" });
  cases.push_back({ "tck last streamline not ended",
    MRtrixBytes("mrtrix tracks", "", { 1, 2, 3, nan, nan, nan, 4, 5, 6, inf, inf, inf }), ".tck",
    "not ended" });
  cases.push_back({ "empty file", "", ".tck", "empty" });
  cases.push_back({ "trk-named text", "hello world", ".trk", "shorter than a TrackVis header" });

  TrkFile trk;
  trk.Count = 2;
  trk.NumberOfScalars = 1;
  trk.ScalarNames = { "FA" };
  trk.NumberOfProperties = 1;
  trk.AddStreamline(2, { 1, 2, 3, 0.5f, 4, 5, 6, 0.6f }, { 9 });
  trk.AddStreamline(1, { 7, 8, 9, 0.7f }, { 10 });
  {
    TrkFile t = trk;
    t.Magic = std::string("TRACX\0", 6);
    cases.push_back({ "trk wrong magic", t.Bytes(), ".trk", "TRACK" });
    t.Magic = std::string("TRACK\0", 6);
    t.HeaderSize = 999;
    cases.push_back({ "trk wrong hdr_size", t.Bytes(), ".trk", "hdr_size" });
    t.HeaderSize = 1000;
    t.Version = 7;
    cases.push_back({ "trk version 7", t.Bytes(), ".trk", "version" });
    t.Version = 2;
    t.Count = 2000000000;
    cases.push_back({ "trk count exceeding the file", t.Bytes(), ".trk", "exceeds" });
    t.Count = 3;
    cases.push_back({ "trk fewer streamlines than n_count", t.Bytes(), ".trk", "holds" });
    t.Count = 2;
    const std::string b = t.Bytes();
    cases.push_back(
      { "trk truncated inside a record", b.substr(0, b.size() - 6), ".trk", "past the end" });
    t.NumberOfScalars = 3; // the records hold 1
    cases.push_back({ "trk wrong n_scalars", t.Bytes(), ".trk", "" });
    t.NumberOfScalars = 1;
    t.ScalarNames = { std::string("FA\0"
                                  "4",
      4) };
    cases.push_back({ "trk names cover more than n_scalars", t.Bytes(), ".trk", "names cover" });
    t.ScalarNames = { "FA" };
    TrkFile n = t;
    n.Records.clear();
    n.Count = 1;
    n.AddStreamline(-5, { 1, 2, 3, 4 }, { 9 });
    cases.push_back({ "trk negative point count", n.Bytes(), ".trk", "negative point count" });
    n.Records.clear();
    n.Count = 2;
    n.AddStreamline(2, { 1, 2, 3, 0.5f, nan, 5, 6, 0.6f }, { 9 });
    n.AddStreamline(1, { 7, 8, 9, 0.7f }, { 10 });
    cases.push_back({ "trk NaN coordinates", n.Bytes(), ".trk", "NaN or infinite coordinates" });
    TrkFile tiny = t; // finite points, but beyond float32 once divided by the voxel size
    tiny.VoxelSize[0] = 1e-38f;
    cases.push_back(
      { "trk voxel size 1e-38", tiny.Bytes(), ".trk", "after the voxel-mm to RAS+ map" });
    n.VoxelSize[1] = 0;
    cases.push_back({ "trk zero voxel size", n.Bytes(), ".trk", "voxel size" });
  }

  vtkNew<vtkTractogramReader> reader;
  h.Watch(reader);
  for (const Case& c : cases)
  {
    const std::string path = OutDir + "/TestTractogramBadInput" + c.Extension;
    WriteBytes(path, c.Bytes);
    reader->SetFileName(path.c_str());
    const auto t0 = std::chrono::steady_clock::now();
    const bool ok = h.Run(reader);
    const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    vtkPolyData* out = reader->GetOutput();
    const std::string msg = reader->GetLastErrorMessage();
    std::cout << c.Name << ": " << msg << std::endl;
    SV_CHECK_MSG(status, !ok, c.Name << " was accepted");
    SV_CHECK_MSG(status, out->GetNumberOfPoints() == 0 && out->GetNumberOfCells() == 0,
      c.Name << " left a partly filled output");
    SV_CHECK_MSG(status, msg.find(c.Expected) != std::string::npos,
      c.Name << ": the message does not say \"" << c.Expected << "\"");
    SV_CHECK_MSG(status, seconds < 2.0, c.Name << " took " << seconds << " s");
  }
  // the good ones do read (the cases above differ from them in one thing only)
  for (const std::pair<std::string, std::string>& g :
    { std::make_pair(good, std::string(".tck")), std::make_pair(trk.Bytes(), std::string(".trk")) })
  {
    const std::string path = OutDir + "/TestTractogramBadInput-good" + g.second;
    WriteBytes(path, g.first);
    reader->SetFileName(path.c_str());
    SV_CHECK_MSG(status, h.Run(reader) && reader->GetOutput()->GetNumberOfPoints() == 3, h.Error());
  }
  // Sparse files four times this machine's memory (.tck and .trk): refused
  // before anything is read or allocated.
  {
    vtksys::SystemInformation info;
    const double bytes = 4.0 * static_cast<double>(info.GetHostMemoryTotal()) * 1024.0;
    for (const std::pair<std::string, std::string>& g :
      { std::make_pair(good.substr(0, good.find("END\n") + 4), std::string(".tck")),
        std::make_pair(trk.Header(), std::string(".trk")) })
    {
      const std::string path = OutDir + "/TestTractogramBadInput-sparse" + g.second;
      {
        std::ofstream f(path, std::ios::binary | std::ios::trunc);
        f.write(g.first.data(), static_cast<std::streamsize>(g.first.size()));
        f.seekp(static_cast<std::streamoff>(bytes));
        f.put('\0');
      }
      reader->SetFileName(path.c_str());
      const auto t0 = std::chrono::steady_clock::now();
      const bool ok = h.Run(reader);
      const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      const std::string msg = reader->GetLastErrorMessage();
      std::cout << "sparse " << g.second << " of " << bytes / (1 << 30) << " GiB: " << msg
                << std::endl;
      SV_CHECK_MSG(status, !ok && msg.find("memory") != std::string::npos && seconds < 2.0,
        g.second << " sparse file: " << msg << " after " << seconds << " s");
      std::remove(path.c_str());
    }
  }
  reader->SetFileName((OutDir + "/does-not-exist.tck").c_str());
  SV_CHECK(status, !h.Run(reader));
  SV_CHECK(
    status, std::string(reader->GetLastErrorMessage()).find("does not exist") != std::string::npos);

  //----------------------------------------------------------------------------
  // Writer.
  vtkNew<vtkPolyData> pd;
  vtkNew<vtkPoints> pts;
  pts->InsertNextPoint(0, 0, 0);
  pts->InsertNextPoint(1, nan, 0);
  vtkNew<vtkCellArray> cells;
  const vtkIdType ids[2] = { 0, 1 };
  cells->InsertNextCell(2, ids);
  pd->SetPoints(pts);
  pd->SetLines(cells);
  vtkNew<vtkTractogramWriter> writer;
  h.Watch(writer);
  writer->SetInputData(pd);
  for (const char* ext : { ".tck", ".trk" })
  {
    const std::string path = OutDir + "/TestTractogramBadInput-nan" + ext;
    WriteBytes(path, "old");
    writer->SetFileName(path.c_str());
    SV_CHECK(status, !h.Run(writer));
    SV_CHECK(status, h.Error().find("NaN") != std::string::npos);
    SV_CHECK(status, ReadBytes(path) == "old" || ReadBytes(path).empty());
  }
  pts->SetPoint(1, 1, 0, 0);
  pts->Modified();
  writer->SetFileName((OutDir + "/TestTractogramBadInput-w.vtk").c_str());
  SV_CHECK(status, !h.Run(writer));
  SV_CHECK(status, h.Error().find("extension") != std::string::npos);
  writer->SetFileName((OutDir + "/TestTractogramBadInput-w.trk").c_str());
  writer->AddPointArrayName("NoSuchArray");
  SV_CHECK(status, !h.Run(writer));
  SV_CHECK(status, h.Error().find("NoSuchArray") != std::string::npos);
  writer->RemoveAllPointArrayNames();
  for (int i = 0; i < 11; ++i)
  {
    vtkNew<vtkFloatArray> a;
    a->SetName(("A" + std::to_string(i)).c_str());
    a->SetNumberOfTuples(2);
    a->FillValue(i);
    pd->GetPointData()->AddArray(a);
    writer->AddPointArrayName(a->GetName());
  }
  SV_CHECK(status, !h.Run(writer));
  SV_CHECK(status, h.Error().find("at most 10") != std::string::npos);
  writer->RemoveAllPointArrayNames();
  writer->AddPointArrayName("A1");
  SV_CHECK_MSG(status, h.Run(writer), h.Error());
  return status.Result();
}
