// The pixel check of the GL test programs in tests/steady: one pixel read back with
// glReadPixels and compared with what it should be, failures counted and printed.
#pragma once

#include <GL/gl.h>

#include <cstdint>
#include <cstdio>

namespace steady {

/// Checks that failed; the programs exit with 1 when there are any.
inline int failures = 0;

/// Reads pixel (x, y) of the current context back as RGBA8 and counts a failure, printed with
/// `what`, unless it is `want`.
inline void expect_pixel(int x, int y, const std::uint8_t want[4], const char* what) {
  std::uint8_t got[4] = {};
  glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, got);
  for (int c = 0; c < 4; ++c) {
    if (got[c] != want[c]) {
      std::printf("FAIL %s: pixel (%d, %d) is %d %d %d %d, expected %d %d %d %d\n", what, x, y, got[0], got[1],
                  got[2], got[3], want[0], want[1], want[2], want[3]);
      ++failures;
      return;
    }
  }
}

}  // namespace steady
