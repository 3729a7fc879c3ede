//VTK::System::Dec
// OFB construction, fragment stage. One fragment is one sample at a cell centre.
// Without FILL: count the samples of each cell. With FILL: write each sample to
// its slot (the cell's offset plus a slot taken by counting the counter back to 0),
// with its depth (world units from the grid plane: the triangle's plane at the
// cell centre), triangle and barycentrics (clamped to the triangle), as the CPU
// sampler does.

flat in int gridAxis;
flat in uint triangleId;
flat in ivec2 corner;
flat in dvec3 depthPlane;
flat in vec2 vertex0;
flat in vec4 baryCoeffs;

uniform uvec3 gridBase;   // global index of the first cell of each grid
uniform ivec3 gridWidth;  // cells along u of each grid
uniform ivec3 gridHeight; // cells along v of each grid
uniform double cellSize;  // world units per cell

layout(std430, binding = 0) buffer Counts
{
  uint counts[];
};

#ifdef FILL
layout(std430, binding = 1) readonly buffer Offsets
{
  uint offsets[];
};
layout(std430, binding = 2) writeonly buffer Depths
{
  float depths[];
};
layout(std430, binding = 3) writeonly buffer Triangles
{
  uint triangles[];
};
layout(std430, binding = 4) writeonly buffer FirstWeights
{
  float w1s[];
};
layout(std430, binding = 6) writeonly buffer SecondWeights
{
  float w2s[];
};
#endif

void main()
{
  ivec2 c = ivec2(gl_FragCoord.xy);
  if (c.x < 0 || c.y < 0 || c.x >= gridWidth[gridAxis] || c.y >= gridHeight[gridAxis])
  {
    return;
  }
  uint cell = gridBase[gridAxis] + uint(c.y) * uint(gridWidth[gridAxis]) + uint(c.x);
#ifndef FILL
  atomicAdd(counts[cell], 1u);
#else
  uint slot = offsets[cell] + atomicAdd(counts[cell], 0xFFFFFFFFu) - 1u;
  vec2 fromCorner = vec2(c - corner) + 0.5;
  dvec2 dc = dvec2(fromCorner);
  depths[slot] = float((depthPlane.x + depthPlane.y * dc.x + depthPlane.z * dc.y) * cellSize);
  vec2 d = fromCorner - vertex0;
  float w1 = clamp(baryCoeffs.x * d.x + baryCoeffs.y * d.y, 0.0, 1.0);
  float w2 = clamp(baryCoeffs.z * d.x + baryCoeffs.w * d.y, 0.0, 1.0 - w1);
  triangles[slot] = triangleId;
  w1s[slot] = w1;
  w2s[slot] = w2;
#endif
}
