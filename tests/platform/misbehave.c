/* A program that misbehaves on purpose, for `shadelab run`'s robustness tests (tests/platform):
     misbehave crash      dies of SIGSEGV
     misbehave hang       never ends (and never shows a frame)
     misbehave status N   exits with status N at once */
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

int main(int argc, char** argv) {
  if (argc > 1 && strcmp(argv[1], "crash") == 0) {
    signal(SIGSEGV, SIG_DFL); /* die of the signal even where a sanitizer catches SIGSEGV */
    raise(SIGSEGV);
  }
  if (argc > 1 && strcmp(argv[1], "hang") == 0) {
    for (;;) pause();
  }
  if (argc > 2 && strcmp(argv[1], "status") == 0) return atoi(argv[2]);
  return 99;
}
