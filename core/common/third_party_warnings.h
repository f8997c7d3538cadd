// Brackets third-party headers (stb) whose implementations trip our warning flags.
#pragma once

#if defined(__GNUC__)
#define SAGRID_THIRD_PARTY_BEGIN                                             \
  _Pragma("GCC diagnostic push")                                            \
      _Pragma("GCC diagnostic ignored \"-Wmissing-field-initializers\"")   \
          _Pragma("GCC diagnostic ignored \"-Wsign-compare\"")             \
              _Pragma("GCC diagnostic ignored \"-Wunused-function\"")      \
                  _Pragma("GCC diagnostic ignored \"-Wimplicit-fallthrough\"")
#define SAGRID_THIRD_PARTY_END _Pragma("GCC diagnostic pop")
#else
#define SAGRID_THIRD_PARTY_BEGIN
#define SAGRID_THIRD_PARTY_END
#endif
