/* GL 1.3's multisample state without a multisample buffer (GL 1.5 section 3.2.1): the
 * enables (GL_MULTISAMPLE, GL_SAMPLE_ALPHA_TO_COVERAGE, GL_SAMPLE_ALPHA_TO_ONE,
 * GL_SAMPLE_COVERAGE) and glSampleCoverage's value and invert, in every query type, through
 * glPushAttrib(GL_MULTISAMPLE_BIT / GL_ENABLE_BIT) and display lists; GL_SAMPLE_BUFFERS and
 * GL_SAMPLES 0. Drawing with all of it enabled (translucent, blended triangles) changes no
 * pixel compared with drawing without it. */
#define GL_GLEXT_PROTOTYPES
#include "conf.h"

static void record(ConfContext* c, const char* when) {
  static const GLenum caps[] = {GL_MULTISAMPLE, GL_SAMPLE_ALPHA_TO_COVERAGE, GL_SAMPLE_ALPHA_TO_ONE, GL_SAMPLE_COVERAGE};
  static const GLenum values[] = {GL_SAMPLE_COVERAGE_VALUE, GL_SAMPLE_COVERAGE_INVERT, GL_SAMPLE_BUFFERS, GL_SAMPLES,
                                  GL_MULTISAMPLE, GL_SAMPLE_COVERAGE};
  char label[128];
  for (unsigned k = 0; k < sizeof caps / sizeof caps[0]; ++k) {
    snprintf(label, sizeof label, "%s IsEnabled 0x%x", when, caps[k]);
    conf_value(c, label, glIsEnabled(caps[k]));
  }
  for (unsigned k = 0; k < sizeof values / sizeof values[0]; ++k) {
    GLboolean b = 7;
    GLint i = -7;
    GLfloat f = -7;
    GLdouble d = -7;
    glGetBooleanv(values[k], &b), glGetIntegerv(values[k], &i), glGetFloatv(values[k], &f), glGetDoublev(values[k], &d);
    snprintf(label, sizeof label, "%s get 0x%x", when, values[k]);
    const double v[4] = {b, i, f, d};
    conf_values(c, label, v, 4);
  }
  snprintf(label, sizeof label, "%s error", when);
  conf_error(c, label);
}

static void scene(void) {
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  for (int k = 0; k < 6; ++k) {
    glBegin(GL_TRIANGLES);
    glColor4f(1.0f - 0.15f * k, 0.2f + 0.1f * k, 0.5f, 0.2f + 0.13f * k);
    glVertex2f(-0.9f + 0.25f * k, -0.8f);
    glColor4f(0.2f, 1.0f, 0.3f * k, 0.9f - 0.1f * k);
    glVertex2f(-0.3f + 0.25f * k, -0.7f);
    glColor4f(0.1f * k, 0.3f, 1.0f, 0.5f);
    glVertex2f(-0.6f + 0.2f * k, 0.9f);
    glEnd();
  }
  glDisable(GL_BLEND);
}

int main(int argc, char** argv) {
  ConfContext c;
  if (!conf_init(&c, argc, argv, 256, 128)) return 1;
  record(&c, "initial");
  glClearColor(0.2f, 0.2f, 0.2f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  conf_panel(&c, 0, 0, 2, 1);
  scene();

  glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
  glEnable(GL_SAMPLE_ALPHA_TO_ONE);
  glEnable(GL_SAMPLE_COVERAGE);
  glSampleCoverage(0.25f, GL_TRUE);
  record(&c, "all enabled");
  conf_panel(&c, 1, 0, 2, 1);
  scene();  /* no multisample buffer: the same pixels */

  glSampleCoverage(1.5f, GL_FALSE), record(&c, "coverage 1.5");
  glSampleCoverage(-0.5f, GL_TRUE), record(&c, "coverage -0.5");
  glSampleCoverage(0.75f, GL_TRUE), record(&c, "invert");
  glPushAttrib(GL_MULTISAMPLE_BIT);
  glDisable(GL_MULTISAMPLE);
  glDisable(GL_SAMPLE_COVERAGE);
  glSampleCoverage(0.125f, GL_FALSE);
  record(&c, "changed under GL_MULTISAMPLE_BIT");
  glPopAttrib();
  record(&c, "popped GL_MULTISAMPLE_BIT");
  glPushAttrib(GL_ENABLE_BIT);
  glDisable(GL_SAMPLE_ALPHA_TO_ONE);
  glDisable(GL_MULTISAMPLE);
  glSampleCoverage(0.5f, GL_FALSE);
  glPopAttrib();
  record(&c, "popped GL_ENABLE_BIT");
  glPushAttrib(GL_COLOR_BUFFER_BIT);
  glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
  glPopAttrib();
  record(&c, "popped GL_COLOR_BUFFER_BIT");

  GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glSampleCoverage(0.375f, GL_TRUE);
  glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
  glEndList();
  record(&c, "list compiled");
  glCallList(list);
  record(&c, "list called");

  glBegin(GL_TRIANGLES);
  glSampleCoverage(0.5f, GL_FALSE);
  glEnd();
  conf_error(&c, "SampleCoverage in glBegin");
  record(&c, "after glBegin");
  return conf_finish(&c);
}
