// SPDX-License-Identifier: BSD-3-Clause
// A main() for the fuzz targets when they are built without libFuzzer (the
// normal build, GCC): runs LLVMFuzzerTestOneInput once on every file named on
// the command line (or every file in a named folder), as libFuzzer does when
// given files. ctest uses it to replay the seeds and the regression inputs.
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "vtksys/Directory.hxx"
#include "vtksys/SystemTools.hxx"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

namespace
{
int RunFile(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    std::fprintf(stderr, "ERROR: cannot open %s\n", path.c_str());
    return 1;
  }
  const std::vector<char> bytes(
    (std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::printf("Running: %s (%zu bytes)\n", path.c_str(), bytes.size());
  std::fflush(stdout);
  LLVMFuzzerTestOneInput(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
  return 0;
}
}

int main(int argc, char* argv[])
{
  int failures = 0, count = 0;
  for (int a = 1; a < argc; ++a)
  {
    const std::string arg = argv[a];
    if (!arg.empty() && arg[0] == '-')
    {
      continue; // libFuzzer options (-runs=..., ...) are ignored here
    }
    if (vtksys::SystemTools::FileIsDirectory(arg))
    {
      vtksys::Directory dir;
      dir.Load(arg);
      for (unsigned long i = 0; i < dir.GetNumberOfFiles(); ++i)
      {
        const std::string name = dir.GetFile(i);
        const std::string path = arg + "/" + name;
        if (name[0] != '.' && !vtksys::SystemTools::FileIsDirectory(path))
        {
          failures += RunFile(path);
          ++count;
        }
      }
    }
    else
    {
      failures += RunFile(arg);
      ++count;
    }
  }
  std::printf("Executed %d inputs, %d could not be opened\n", count, failures);
  return failures == 0 && count > 0 ? 0 : 1;
}
