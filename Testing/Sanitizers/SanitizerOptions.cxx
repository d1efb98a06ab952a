// SPDX-License-Identifier: GPL-3.0-or-later
// Default sanitizer options of the test programs of the sanitizer build, so
// that ctest, gtest's test discovery and a developer running a test by hand
// all use the same suppressions (for the uninstrumented system libraries
// only) without setting environment variables. Variables set by the user
// (ASAN_OPTIONS, ...) still take precedence.
#ifndef MEDIALAXIS_SANITIZER_DIR
#error "MEDIALAXIS_SANITIZER_DIR must name the folder of the suppression files"
#endif

extern "C"
{
  const char* __asan_default_options()
  {
    return "detect_stack_use_after_return=1:strict_init_order=1:check_initialization_order=1";
  }
  const char* __lsan_default_options()
  {
    return "suppressions=" MEDIALAXIS_SANITIZER_DIR "/lsan.supp:print_suppressions=0";
  }
  const char* __ubsan_default_options()
  {
    return "suppressions=" MEDIALAXIS_SANITIZER_DIR "/ubsan.supp:print_stacktrace=1";
  }
}
