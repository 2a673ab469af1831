// Deliberately breaks every core rule, so the symbol check can be seen to fail.
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

void* volatile kerf_symbol_probe_sink;  // keeps the optimiser from eliding malloc/free

int kerf_symbol_probe_bad(int n) {
  int* p = new int[static_cast<unsigned>(n)];
  void* q = std::malloc(16);
  kerf_symbol_probe_sink = q;
  std::printf("%d\n", n);
  if (n < 0) throw std::runtime_error("negative");
  std::free(q);
  const int r = p[0];
  delete[] p;
  return r;
}
