/*
 * How fast this machine hands out fresh memory: maps MB mebibytes, writes one byte per 4 KiB
 * page (every page faulted in and cleared by the kernel, and backed by the host on a virtual
 * machine), then writes them all again (memory already there), and prints both rates.
 * With a second argument the mapping is marked for transparent huge pages first.
 *
 *   cc -O2 -o /tmp/first-touch scripts/first-touch.c
 *   /tmp/first-touch 40; /tmp/first-touch 3000; /tmp/first-touch 3000 huge
 *
 * docs/BENCHMARK.md ("The demo's generation on all cores") has the figures of this machine.
 */
#define _GNU_SOURCE
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <time.h>

static double Now(void)
{
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec + t.tv_nsec * 1e-9;
}

int main(int argc, char** argv)
{
  if (argc < 2)
  {
    fprintf(stderr, "usage: %s MEBIBYTES [huge]\n", argv[0]);
    return 2;
  }
  const size_t huge = (size_t)2 << 20;
  const size_t bytes = (size_t)atol(argv[1]) << 20;
  char* mapped =
    mmap(NULL, bytes + huge, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (mapped == MAP_FAILED)
  {
    perror("mmap");
    return 1;
  }
  char* p = (char*)(((size_t)mapped + huge - 1) & ~(huge - 1));
  if (argc > 2)
  {
    madvise(p, bytes, MADV_HUGEPAGE);
  }
  double t = Now();
  for (size_t i = 0; i < bytes; i += 4096)
  {
    p[i] = 1;
  }
  const double first = Now() - t;
  t = Now();
  memset(p, 2, bytes);
  const double second = Now() - t;
  const double gib = bytes / 1073741824.0;
  printf("%s MiB%s: first touch %.3f s (%.2f GB/s), written again %.3f s (%.2f GB/s)\n", argv[1],
         argc > 2 ? " (huge pages)" : "", first, gib / first, second, gib / second);
  return 0;
}
