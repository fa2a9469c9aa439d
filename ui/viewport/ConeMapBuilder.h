// ConeMapBuilder: the cone technique's cone map, built off the GUI thread (seconds for a large
// height map) for the material shown; the renderer draws with the quadtree, the same exact
// surface, until it is handed over. One build per height map at a time.
#pragma once

#include "core/material/Material.h"
#include "renderer/TextureCache.h"
#include "ui/Forward.h"

#include <QObject>

#include <functional>
#include <optional>

namespace relief::ui::inline viewport {

class ConeMapBuilder : public QObject {
  Q_OBJECT

 public:
  // `deliver` gets each finished map on the GUI thread, with the material it was built for.
  using Deliver = std::function<void(const core::Material&, const core::ConeMap&)>;
  ConeMapBuilder(Deliver deliver, QObject* parent = nullptr);
  ~ConeMapBuilder() override;

  // Starts building `material`'s cone map unless it is already being built.
  void build(const core::Material& material);
  void forget() { m_building.reset(); }  // the renderer that was to get it is gone

 Q_SIGNALS:
  void building(bool on);

 private:
  Deliver m_deliver;
  BackgroundTask* m_task;
  std::optional<renderer::TracedHeightKey> m_building;
};

}  // namespace relief::ui::inline viewport
