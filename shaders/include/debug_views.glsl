// Debug view ids: DEBUG_VIEW is one of these (renderer/ShaderVariant.cpp), in the order of
// core::DebugView. VIEW_RAY is internal: the eye ray per pixel for the CPU error view.
#define VIEW_SHADING 0
#define VIEW_HEIGHT 1
#define VIEW_NORMAL 2
#define VIEW_UV 3
#define VIEW_OFFSET 4
#define VIEW_STEPS 5
#define VIEW_SHADOW 6
#define VIEW_TANGENTS 7
#define VIEW_MIP 8
#define VIEW_DEPTH 9
#define VIEW_RAY 100

#ifndef DEBUG_VIEW
#define DEBUG_VIEW VIEW_SHADING
#endif

// Display scales, shared with the legends the renderer draws (renderer/HeatmapLegend.cpp).
const float kOffsetDisplayTexels = 32.0;  // offset view: +-32 texels span the colour range
const float kMipDisplayLevels = 10.0;     // mip view: levels 0..10 span the heat map
