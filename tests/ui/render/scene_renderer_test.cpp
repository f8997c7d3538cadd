// The viewport uploads the next object's mesh even where the allocator hands the next object's
// document and mesh the addresses of the previous ones, freed as it opened: compared by address
// alone, the previous object's triangles stayed on screen under the next one's fields and points
// (seen curating Sweet Home 3D objects in the window: a microwave drawn under a stove's burners).
#include "ui/render/scene_renderer.h"

#include <gtest/gtest.h>

#include <array>
#include <new>
#include <optional>

#include "support/analytic_meshes.h"
#include "ui/document/annotation_document.h"
#include "ui/gl/gl_context.h"

namespace sagrid::ui {
namespace {

// Two slots for meshes, the first free one taken: an allocator that reuses a freed block at once.
class MeshSlots {
 public:
  std::shared_ptr<const Mesh> make(Mesh mesh) {
    for (std::size_t i = 0; i < m_slots.size(); ++i) {
      if (m_used[i]) continue;
      m_used[i] = true;
      Mesh* placed = new (m_slots[i].bytes) Mesh(std::move(mesh));
      return std::shared_ptr<const Mesh>(placed, [this, i](const Mesh* p) {
        p->~Mesh();
        m_used[i] = false;
      });
    }
    throw std::bad_alloc();
  }

 private:
  struct alignas(Mesh) Slot {
    unsigned char bytes[sizeof(Mesh)];
  };
  std::array<Slot, 2> m_slots{};
  std::array<bool, 2> m_used{};
};

TEST(SceneRenderer, TheNextObjectsMeshIsUploadedWhereItTakesThePreviousOnesAddress) {
  ContextOptions options;
  options.width = 64;
  options.height = 64;
  const auto gl = createGlContext(GlBackend::Egl, options);
  MeshSlots slots;
  std::optional<AnnotationDocument> document;  // one place: the next document takes its address
  SceneRenderer scene;

  document.emplace(slots.make(sagrid::test::box({0, 0, 0}, {1, 1, 0.1f})), ObjectLabels{}, "");
  scene.sync(&*document, std::nullopt, ViewSettings{});
  EXPECT_EQ(scene.mesh().indexCount(), 36);

  document.reset();  // the queue moves on: the previous object's document and mesh go
  Mesh twoBoxes = sagrid::test::box({0, 0, 0}, {0.2f, 0.2f, 1});
  sagrid::test::append(twoBoxes, sagrid::test::box({0.5f, 0, 0}, {0.7f, 0.2f, 1}));
  document.emplace(slots.make(std::move(twoBoxes)), ObjectLabels{}, "");
  scene.sync(&*document, std::nullopt, ViewSettings{});
  EXPECT_EQ(scene.mesh().indexCount(), 72);
}

}  // namespace
}  // namespace sagrid::ui
