// Command-line help shared by the benchmark programs: each program passes
// its usage text, and `-h` or `--help` anywhere on the command line prints it
// and ends the program before any work starts.
#ifndef BenchmarkUsage_h
#define BenchmarkUsage_h

#include <cstdio>
#include <cstring>

namespace splineviz_benchmark
{
/// True (after printing `usage` to stdout) when -h or --help was given.
inline bool HelpRequested(int argc, char* argv[], const char* usage)
{
  for (int i = 1; i < argc; ++i)
  {
    if (!std::strcmp(argv[i], "-h") || !std::strcmp(argv[i], "--help"))
    {
      std::fputs(usage, stdout);
      return true;
    }
  }
  return false;
}

/// For "--key value" parsers: an option without its value is an error.
inline bool MissingOptionValue(int argc, char* argv[], const char* usage)
{
  if (argc % 2 == 0)
  {
    std::fprintf(stderr, "option %s needs a value\n%s", argv[argc - 1], usage);
    return true;
  }
  return false;
}
}

#endif
