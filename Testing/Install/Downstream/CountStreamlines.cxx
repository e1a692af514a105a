// SPDX-License-Identifier: BSD-3-Clause
// Prints the number of streamlines and points of a .tck/.trk file read with
// the installed SplineViz (vtkTractogramReader); exit status 1 when the file
// cannot be read.
#include <vtkExecutive.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkTractogramReader.h>

#include <iostream>

int main(int argc, char* argv[])
{
  if (argc != 2)
  {
    std::cerr << "usage: " << argv[0] << " file.tck\n";
    return 2;
  }
  vtkNew<vtkTractogramReader> reader;
  reader->SetFileName(argv[1]);
  if (!reader->GetExecutive()->Update())
  {
    std::cerr << "could not read " << argv[1] << "\n";
    return 1;
  }
  vtkPolyData* lines = reader->GetOutput();
  std::cout << "streamlines: " << lines->GetNumberOfLines()
            << " points: " << lines->GetNumberOfPoints() << "\n";
  return 0;
}
