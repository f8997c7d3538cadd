// Debian's libimgui.a is built against the system stb instead of its bundled copies and leaves
// stb_truetype / stb_rect_pack undefined; their implementations are compiled here, once, for the
// UI only (core compiles stb_image/stb_image_write in core/common/stb_impl.cpp).
#define STB_RECT_PACK_IMPLEMENTATION
#define STB_TRUETYPE_IMPLEMENTATION

#include "core/common/third_party_warnings.h"

SAGRID_THIRD_PARTY_BEGIN
#include <stb_rect_pack.h>
#include <stb_truetype.h>
SAGRID_THIRD_PARTY_END
