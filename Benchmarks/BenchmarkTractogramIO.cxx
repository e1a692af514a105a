// SPDX-License-Identifier: BSD-3-Clause
// Benchmark of vtkTractogramReader / vtkTractogramWriter on a whole-brain-
// sized tractogram (10 M points by default), against the VTK way of storing
// the same polylines (vtkXMLPolyDataWriter/Reader, binary, raw appended data,
// no compression: VTK's fastest), in one run.
//
// The tractogram: smooth random curves (100 points each by default) with a
// 1-component point array (FA) and a 1-component cell array (Length).
// Written once as .tck (+ FA .tsf), .trk (FA per point, Length per
// streamline) and .vtp; each file is then read several times (the median
// is printed; the files are in the page cache, so these are parse times,
// not disk times) with the reader on 1 thread (vtkSMPTools Sequential) and
// on all cores (STDThread), and vtkXMLPolyDataReader. The read output is
// checked against the data written (every point).
//
//   BenchmarkTractogramIO [--points N] [--length M] [--repeat R] [--dir DIR] [--keep 1]
#include "BenchmarkCommon.h"

#include "vtkTractogramReader.h"
#include "vtkTractogramWriter.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkXMLPolyDataReader.h"
#include "vtkXMLPolyDataWriter.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <string>
#include <thread>
#include <vector>

namespace
{
const char* Usage =
  "BenchmarkTractogramIO [--points N] [--length M] [--repeat R] [--dir DIR] [--keep 1]\n"
  "  --points  total number of points (default 10000000)\n"
  "  --length  points per streamline (default 100)\n"
  "  --repeat  reads per file and reader (default 3; the median is printed)\n"
  "  --dir     where the files go (default /tmp)\n"
  "  --keep    1: keep the files (default: removed)\n";

vtkSmartPointer<vtkPolyData> Tractogram(vtkIdType nPoints, int length)
{
  const vtkIdType nLines = nPoints / length;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(nLines * length);
  vtkNew<vtkFloatArray> fa, len;
  fa->SetName("FA");
  fa->SetNumberOfTuples(nLines * length);
  len->SetName("Length");
  len->SetNumberOfTuples(nLines);
  vtkNew<vtkIdTypeArray> offsets, conn;
  offsets->SetNumberOfValues(nLines + 1);
  conn->SetNumberOfValues(nLines * length);
  float* p = static_cast<vtkFloatArray*>(points->GetData())->GetPointer(0);
  vtkSMPTools::For(0, nLines,
    [&](vtkIdType l0, vtkIdType l1)
    {
      for (vtkIdType l = l0; l < l1; ++l)
      {
        // a smooth curve through a 160 mm brain-sized box
        const double a = 0.37 * l, b = 0.011 * l, c = 0.0007 * l;
        double x[3] = { 70 * std::sin(a), 80 * std::cos(1.3 * a + b), 60 * std::sin(b + c) };
        for (int j = 0; j < length; ++j)
        {
          const vtkIdType id = l * length + j;
          x[0] += 0.8 * std::cos(0.05 * j + a);
          x[1] += 0.8 * std::sin(0.04 * j + b);
          x[2] += 0.5 * std::cos(0.03 * j + c);
          for (int k = 0; k < 3; ++k)
          {
            p[3 * id + k] = static_cast<float>(x[k]);
          }
          fa->SetValue(id, static_cast<float>(0.5 + 0.4 * std::sin(0.1 * j + a)));
          conn->SetValue(id, id);
        }
        len->SetValue(l, static_cast<float>(length));
        offsets->SetValue(l, l * length);
      }
    });
  offsets->SetValue(nLines, nLines * length);
  vtkNew<vtkCellArray> cells;
  cells->SetData(offsets, conn);
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  pd->SetPoints(points);
  pd->SetLines(cells);
  pd->GetPointData()->AddArray(fa);
  pd->GetCellData()->AddArray(len);
  return pd;
}

double FileMB(const std::string& name)
{
  std::ifstream in(name, std::ios::binary | std::ios::ate);
  return in ? static_cast<double>(in.tellg()) / 1e6 : 0.0;
}

// Median wall time (and the CPU time of that run) of `read` over `repeat` runs.
struct Timing
{
  double Wall = 0, CPU = 0;
};
Timing Median(int repeat, const std::function<void()>& read)
{
  std::vector<std::pair<double, double>> runs;
  for (int r = 0; r < repeat; ++r)
  {
    const double w0 = splineviz_benchmark::Now(), c0 = splineviz_benchmark::CPUTime();
    read();
    runs.emplace_back(splineviz_benchmark::Now() - w0, splineviz_benchmark::CPUTime() - c0);
  }
  std::sort(runs.begin(), runs.end());
  return { runs[runs.size() / 2].first, runs[runs.size() / 2].second };
}

bool SamePoints(vtkPolyData* a, vtkPolyData* b, double tolerance)
{
  if (a->GetNumberOfPoints() != b->GetNumberOfPoints() ||
    a->GetNumberOfLines() != b->GetNumberOfLines())
  {
    return false;
  }
  auto* pa = static_cast<vtkFloatArray*>(a->GetPoints()->GetData());
  auto* pb = static_cast<vtkFloatArray*>(b->GetPoints()->GetData());
  const float* x = pa->GetPointer(0);
  const float* y = pb->GetPointer(0);
  for (vtkIdType i = 0; i < 3 * a->GetNumberOfPoints(); ++i)
  {
    if (std::abs(x[i] - y[i]) > tolerance)
    {
      return false;
    }
  }
  return true;
}
}

int main(int argc, char* argv[])
{
  namespace B = splineviz_benchmark;
  if (B::HelpRequested(argc, argv, Usage) || B::MissingOptionValue(argc, argv, Usage))
  {
    return 0;
  }
  vtkIdType nPoints = 10000000;
  int length = 100, repeat = 3, keep = 0;
  std::string dir = "/tmp";
  for (int i = 1; i + 1 < argc; i += 2)
  {
    const std::string key = argv[i], value = argv[i + 1];
    if (key == "--points")
      nPoints = std::atoll(value.c_str());
    else if (key == "--length")
      length = std::atoi(value.c_str());
    else if (key == "--repeat")
      repeat = std::max(1, std::atoi(value.c_str()));
    else if (key == "--dir")
      dir = value;
    else if (key == "--keep")
      keep = std::atoi(value.c_str());
    else
    {
      std::fprintf(stderr, "unknown option %s\n%s", key.c_str(), Usage);
      return 1;
    }
  }
  if (nPoints < length || length < 2)
  {
    std::fprintf(stderr, "need --points >= --length >= 2\n");
    return 1;
  }
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  vtkSMPTools::SetBackend("STDThread");
  vtkSMPTools::Initialize(cores);
  auto lines = Tractogram(nPoints, length);
  std::printf("tractogram: %lld streamlines x %d points = %lld points; %d cores\n",
    static_cast<long long>(lines->GetNumberOfLines()), length,
    static_cast<long long>(lines->GetNumberOfPoints()), cores);

  const std::string tck = dir + "/BenchmarkTractogramIO.tck";
  const std::string trk = dir + "/BenchmarkTractogramIO.trk";
  const std::string vtp = dir + "/BenchmarkTractogramIO.vtp";
  const std::string tsf = vtkTractogramWriter::ScalarFileName(tck, "FA");
  auto timeOnce = [](const std::function<void()>& f)
  {
    const double t0 = B::Now();
    f();
    return B::Now() - t0;
  };
  vtkNew<vtkTractogramWriter> writer;
  writer->SetInputData(lines);
  writer->AddPointArrayName("FA");
  writer->SetFileName(tck.c_str());
  const double wTck = timeOnce([&] { writer->Write(); });
  writer->AddCellArrayName("Length");
  writer->SetFileName(trk.c_str());
  const double wTrk = timeOnce([&] { writer->Write(); });
  vtkNew<vtkXMLPolyDataWriter> xml;
  xml->SetInputData(lines);
  xml->SetDataModeToAppended();
  xml->EncodeAppendedDataOff();
  xml->SetCompressorTypeToNone();
  xml->SetFileName(vtp.c_str());
  const double wVtp = timeOnce([&] { xml->Write(); });
  std::printf("\nwrite (once, 2 cores for ours):\n");
  std::printf("  .tck + .tsf  %6.2f s  %7.1f MB\n", wTck, FileMB(tck) + FileMB(tsf));
  std::printf("  .trk         %6.2f s  %7.1f MB\n", wTrk, FileMB(trk));
  std::printf("  .vtp (VTK)   %6.2f s  %7.1f MB\n", wVtp, FileMB(vtp));

  std::printf("\nread (median of %d, files in the page cache):\n", repeat);
  std::printf(
    "  %-34s %8s %8s %10s %8s\n", "file, reader", "wall s", "CPU s", "Mpoints/s", "vs .vtp");
  vtkNew<vtkXMLPolyDataReader> xmlReader;
  xmlReader->SetFileName(vtp.c_str());
  const Timing tVtp = Median(repeat,
    [&]
    {
      xmlReader->Modified();
      xmlReader->Update();
    });
  const bool vtpOk = SamePoints(xmlReader->GetOutput(), lines, 0.0);
  struct Row
  {
    std::string Label;
    Timing T;
    bool Ok;
  };
  std::vector<Row> rows;
  for (const std::string& file : { tck, trk })
  {
    for (int threads : { 1, cores })
    {
      if (threads == 1)
      {
        vtkSMPTools::SetBackend("Sequential");
      }
      else
      {
        vtkSMPTools::SetBackend("STDThread");
        vtkSMPTools::Initialize(threads);
      }
      vtkNew<vtkTractogramReader> reader;
      reader->SetFileName(file.c_str());
      if (file == tck)
      {
        reader->AddScalarFileName(tsf.c_str());
      }
      const Timing t = Median(repeat,
        [&]
        {
          reader->Modified();
          reader->Update();
        });
      // .tck: exact; .trk: float32 voxel-mm round trip
      const bool ok = SamePoints(reader->GetOutput(), lines, file == tck ? 0.0 : 1e-4) &&
        reader->GetOutput()->GetPointData()->GetArray("FA");
      rows.push_back({ (file == tck ? std::string(".tck + .tsf, ") : std::string(".trk, ")) +
          "vtkTractogramReader, " + std::to_string(threads) + (threads == 1 ? " core" : " cores"),
        t, ok });
    }
  }
  rows.push_back({ ".vtp, vtkXMLPolyDataReader", tVtp, vtpOk });
  for (const Row& r : rows)
  {
    std::printf("  %-34s %8.3f %8.3f %10.1f %8.2f %s\n", r.Label.c_str(), r.T.Wall, r.T.CPU,
      nPoints / r.T.Wall / 1e6, r.T.Wall / tVtp.Wall, r.Ok ? "" : "(WRONG OUTPUT)");
  }
  if (!keep)
  {
    for (const std::string& f : { tck, tsf, trk, vtp })
    {
      std::remove(f.c_str());
    }
  }
  bool allOk = true;
  for (const Row& r : rows)
  {
    allOk = allOk && r.Ok;
  }
  return allOk ? 0 : 1;
}
