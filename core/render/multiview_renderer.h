// CPU multi-view renderer on the Embree SurfaceScene: one primary ray per pixel centre, no GL.
// Renders the views TRELLIS renders with Blender (see trellis_views.h) in a fraction of the time,
// with simple shading (albedo x headlight) instead of path tracing.
#pragma once

#include <functional>
#include <vector>

#include "core/render/rendered_view.h"
#include "core/render/view_camera.h"

namespace sagrid {

struct Mesh;
class SurfaceScene;

class MultiViewRenderer {
 public:
  // Both must outlive the renderer; `scene` must be built from `mesh` (same triangle order),
  // usually the normalized copy of the object.
  MultiViewRenderer(const Mesh& mesh, const SurfaceScene& scene) : m_mesh(mesh), m_scene(scene) {}

  // Renders a size x size view into `out` (buffers reused when already the right size).
  void render(const ViewCamera& camera, int size, RenderedView& out) const;
  RenderedView render(const ViewCamera& camera, int size) const;

  // Renders every view on `threads` workers (std::thread, views interleaved) and hands each
  // finished view to consume(viewIndex, workerIndex, view) on the worker's thread. The view's
  // buffers are reused for the worker's next view, so consumers copy what they keep. An exception
  // from a worker is rethrown here after all workers stopped.
  using ViewConsumer = std::function<void(int viewIndex, int worker, const RenderedView& view)>;
  void renderEach(const std::vector<ViewCamera>& cameras, int size, int threads,
                  const ViewConsumer& consume) const;

 private:
  const Mesh& m_mesh;
  const SurfaceScene& m_scene;
};

}  // namespace sagrid
