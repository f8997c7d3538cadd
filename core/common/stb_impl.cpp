// The one translation unit that compiles the stb_image and stb_image_write implementations;
// everything else includes the headers only.
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STBI_FAILURE_USERMSG

#include "core/common/third_party_warnings.h"

SAGRID_THIRD_PARTY_BEGIN
#include <stb_image.h>
#include <stb_image_write.h>
SAGRID_THIRD_PARTY_END
