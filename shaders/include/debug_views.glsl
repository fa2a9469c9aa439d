// Debug views: DEBUG_VIEW is the number of one of core::DebugView's rows, and VIEW_<NAME> the
// number of each (VIEW_SHADING, VIEW_HEIGHT, ... from the rows' names), all #defined by the
// renderer (renderer/ShaderVariant.cpp, materialTableDefines). VIEW_RAY is internal: the eye
// ray per pixel for the CPU error view.
#define VIEW_RAY 100

#ifndef DEBUG_VIEW
#define DEBUG_VIEW VIEW_SHADING
#endif

// Display scales, shared with the legends the renderer draws (renderer/HeatmapLegend.cpp).
const float kOffsetDisplayTexels = 32.0;  // offset view: +-32 texels span the colour range
const float kMipDisplayLevels = 10.0;     // mip view: levels 0..10 span the heat map
