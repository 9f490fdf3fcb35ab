/* Checks that an example's PNG exists, has the expected size when one is given, and is not
 * blank (at least two different colours); prints how many distinct colours it has (up to 1000).
 *   lecture_check_png IMAGE.png [WIDTH HEIGHT] */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <png.h>

int main(int argc, char** argv) {
  if (argc != 2 && argc != 4) {
    fprintf(stderr, "usage: %s IMAGE.png [WIDTH HEIGHT]\n", argv[0]);
    return 2;
  }
  /* libpng's simplified API: any PNG as 8-bit RGBA. */
  png_image image;
  memset(&image, 0, sizeof image);
  image.version = PNG_IMAGE_VERSION;
  unsigned char* px = NULL;
  if (png_image_begin_read_from_file(&image, argv[1])) {
    image.format = PNG_FORMAT_RGBA;
    px = malloc(PNG_IMAGE_SIZE(image));
    if (px && !png_image_finish_read(&image, NULL, px, 0, NULL)) {
      free(px);
      px = NULL;
    }
  }
  if (!px) {
    fprintf(stderr, "%s: cannot read: %s\n", argv[1],
            image.message[0] ? image.message : "out of memory");
    png_image_free(&image);
    return 1;
  }
  int w = (int)image.width, h = (int)image.height;
  int rc = 0;
  if (argc == 4 && (w != atoi(argv[2]) || h != atoi(argv[3]))) {
    fprintf(stderr, "%s: %dx%d, expected %sx%s\n", argv[1], w, h, argv[2], argv[3]);
    rc = 1;
  }
  enum { kMax = 1000 };
  static unsigned int seen[kMax];
  int distinct = 0;
  for (long i = 0; i < (long)w * h && distinct < kMax; ++i) {
    unsigned int c;
    memcpy(&c, px + 4 * i, 4);
    int found = 0;
    for (int k = 0; k < distinct && !found; ++k) found = seen[k] == c;
    if (!found) seen[distinct++] = c;
  }
  free(px);
  printf("%s: %dx%d, %s%d distinct colours\n", argv[1], w, h, distinct >= kMax ? ">= " : "",
         distinct);
  if (distinct < 2) {
    fprintf(stderr, "%s: blank (one colour)\n", argv[1]);
    rc = 1;
  }
  return rc;
}
