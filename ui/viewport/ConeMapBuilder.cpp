// ConeMapBuilder; see ConeMapBuilder.h.
#include "ui/viewport/ConeMapBuilder.h"

#include "ui/tasks/BackgroundTask.h"

namespace relief::ui::inline viewport {

ConeMapBuilder::ConeMapBuilder(Deliver deliver, QObject* parent)
    : QObject(parent), m_deliver(std::move(deliver)), m_task(new BackgroundTask(this)) {}

ConeMapBuilder::~ConeMapBuilder() {
  m_task->cancel();
  m_task->waitForFinished();
}

void ConeMapBuilder::build(const core::Material& material) {
  const renderer::TracedHeightKey key = renderer::tracedHeightKey(material);
  if (m_building == key)
    return;
  m_building = key;
  Q_EMIT building(true);
  // The snapshot keeps the height's images alive, so its key still names them when it is done.
  m_task->run<core::ConeMap>(
      [material](const core::WorkControl&) { return renderer::buildTracedConeMap(material); },
      [this, material](core::ConeMap&& cones) {
        m_building.reset();
        Q_EMIT building(false);
        m_deliver(material, cones);
      });
}

}  // namespace relief::ui::inline viewport
