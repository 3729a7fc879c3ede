// vtkOFBLookupFS.glsl: declarations and functions that vtkOFBPolyDataMapper inserts into
// the fragment shader of vtkOpenGLPolyDataMapper (with the colour declarations) to colour every
// fragment from the samples of a vtkOFB (paper "Sample-based Surface Coloring", 4.1-4.2).
//
// The mapper defines before this text:
//   OFB_MODE            0 nearest sample, 1 inverse-distance weighting, 2 mipmapped IDW
//   OFB_MAX_LEVELS      size of the per-level uniform arrays
//   OFB_SOURCE_SCALARS  colour from a float sample array through a lookup table, else paint
//   OFB_USE_INTENSITY   a float sample array modulates the colour
//   OFB_USE_NORMALS     painted normals replace the interpolated normal for shading
//
// Units: every position here is in cells of the level being read, measured from the
// low corner of that level's frame; depths are uploaded in the same unit.
// Storage (std430 shader storage blocks, bound by the mapper):
//   ofbOffsets  per level, one prefix sum over the cells of grids X, Y, Z (plus one entry),
//               relative to the level's first sample
//   ofbDepths   per sample, depth along the grid axis, sorted within a cell
//   ofbColors   per sample, RGBA8 packed in a uint (red in the low byte)
//   ofbScalars, ofbIntensity per sample (float); ofbNormals three floats per sample
//   ofbLUT      the lookup table sampled at equal steps over the scalar range

layout(std430) readonly buffer ofbOffsetsBlock { uint ofbOffsets[]; };
layout(std430) readonly buffer ofbDepthsBlock { float ofbDepths[]; };
#ifdef OFB_SOURCE_SCALARS
layout(std430) readonly buffer ofbScalarsBlock { float ofbScalars[]; };
layout(std430) readonly buffer ofbLUTBlock { vec4 ofbLUT[]; };
uniform vec2 ofbScalarRange; // x: low end, y: 1 / (high - low)
uniform int ofbLUTSize;
#else
layout(std430) readonly buffer ofbColorsBlock { uint ofbColors[]; };
#endif
#ifdef OFB_USE_INTENSITY
layout(std430) readonly buffer ofbIntensityBlock { float ofbIntensity[]; };
uniform float ofbIntensityWeight;
#endif
#ifdef OFB_USE_NORMALS
layout(std430) readonly buffer ofbNormalsBlock { float ofbNormals[]; };
uniform mat3 ofbNormalMatrix;
#endif

uniform int ofbNumberOfLevels;
// Level L position = level-0 position * ofbLevelTransform[L].w + ofbLevelTransform[L].xyz
uniform vec4 ofbLevelTransform[OFB_MAX_LEVELS];
uniform int ofbLevelDims[3 * OFB_MAX_LEVELS];     // cells along x, y, z
uniform int ofbLevelCellBase[3 * OFB_MAX_LEVELS]; // first entry of grid a in ofbOffsets
uniform int ofbLevelSampleBase[OFB_MAX_LEVELS];   // first sample of the level
uniform float ofbMipmapBias;
uniform float ofbRadius; // IDW radius in cells (sqrt(3))
uniform int ofbNumberOfGrids; // 3; a uniform so that loops over grids are not unrolled

in vec3 ofbGridVSOutput; // level-0 grid position of the fragment, in cells

struct ofbAccum
{
  vec4 color;
  float scalar;
  float intensity;
  vec3 normal;
  float weight;
};

ofbAccum ofbAccumInit()
{
  ofbAccum acc;
  acc.color = vec4(0.0);
  acc.scalar = 0.0;
  acc.intensity = 0.0;
  acc.normal = vec3(0.0);
  acc.weight = 0.0;
  return acc;
}

vec4 ofbUnpackColor(uint c)
{
  return vec4(float(c & 0xFFu), float((c >> 8u) & 0xFFu), float((c >> 16u) & 0xFFu),
           float(c >> 24u)) / 255.0;
}

void ofbAccumulate(inout ofbAccum acc, int i, float w)
{
#ifdef OFB_SOURCE_SCALARS
  acc.scalar += w * ofbScalars[i];
#else
  acc.color += w * ofbUnpackColor(ofbColors[i]);
#endif
#ifdef OFB_USE_INTENSITY
  acc.intensity += w * ofbIntensity[i];
#endif
#ifdef OFB_USE_NORMALS
  acc.normal += w * vec3(ofbNormals[3 * i], ofbNormals[3 * i + 1], ofbNormals[3 * i + 2]);
#endif
  acc.weight += w;
}

// Sample range [first, end) of cell (iu, iv) of grid a of level L; false outside the grid.
bool ofbCellRange(int L, int a, int iu, int iv, out int first, out int end)
{
  int nu = ofbLevelDims[3 * L + (a + 1) % 3];
  int nv = ofbLevelDims[3 * L + (a + 2) % 3];
  first = 0;
  end = 0;
  if (iu < 0 || iv < 0 || iu >= nu || iv >= nv)
  {
    return false;
  }
  int cell = ofbLevelCellBase[3 * L + a] + iv * nu + iu;
  int base = ofbLevelSampleBase[L];
  first = base + int(ofbOffsets[cell]);
  end = base + int(ofbOffsets[cell + 1]);
  return first < end;
}

// First index of [first, end) whose depth is >= d (binary search).
int ofbLowerBound(int first, int end, float d)
{
  int lo = first;
  int hi = end;
  while (lo < hi)
  {
    int mid = (lo + hi) / 2;
    if (ofbDepths[mid] < d)
    {
      lo = mid + 1;
    }
    else
    {
      hi = mid;
    }
  }
  return lo;
}

// Closest sample of grid a to g (level L units), in the cell under g and at depths within
// one cell (paper 4.1). Returns the sample index or -1; dist2 gets its squared distance.
int ofbNearestInGrid(int L, int a, vec3 g, out float dist2)
{
  dist2 = 1.0e30;
  float u = g[(a + 1) % 3];
  float v = g[(a + 2) % 3];
  float d = g[a];
  int iu = int(floor(u));
  int iv = int(floor(v));
  int first;
  int end;
  if (!ofbCellRange(L, a, iu, iv, first, end))
  {
    return -1;
  }
  int i = ofbLowerBound(first, end, d);
  int best = -1;
  float bestDD = 1.0;
  if (i < end && abs(ofbDepths[i] - d) <= bestDD)
  {
    best = i;
    bestDD = abs(ofbDepths[i] - d);
  }
  if (i > first && abs(ofbDepths[i - 1] - d) <= bestDD)
  {
    best = i - 1;
    bestDD = abs(ofbDepths[i - 1] - d);
  }
  if (best >= 0)
  {
    float du = u - (float(iu) + 0.5);
    float dv = v - (float(iv) + 0.5);
    dist2 = du * du + dv * dv + bestDD * bestDD;
  }
  return best;
}

// Visit the samples of grid a within radius r of g in the 3x3 cells around the cell under g
// (paper 4.2), or with `near` only in the 2x2 cells whose centres are closest to g. With
// idw, accumulate them with Shepard weights ((r - t) / (r t))^2; without, keep the closest
// one in `closest` / `closestDist2`.
void ofbGatherGrid(int L, int a, vec3 g, float r, bool idw, bool near, inout ofbAccum acc,
  inout int closest, inout float closestDist2)
{
  float u = g[(a + 1) % 3];
  float v = g[(a + 2) % 3];
  float d = g[a];
  int u0 = near ? int(floor(u - 0.5)) : int(floor(u)) - 1;
  int v0 = near ? int(floor(v - 0.5)) : int(floor(v)) - 1;
  int u1 = near ? u0 + 1 : u0 + 2;
  int v1 = near ? v0 + 1 : v0 + 2;
  float r2 = r * r;
  for (int jv = v0; jv <= v1; ++jv)
  {
    float dv = v - (float(jv) + 0.5);
    for (int ju = u0; ju <= u1; ++ju)
    {
      float du = u - (float(ju) + 0.5);
      float duv2 = du * du + dv * dv;
      int first;
      int end;
      if (duv2 > r2 || !ofbCellRange(L, a, ju, jv, first, end))
      {
        continue;
      }
      for (int i = ofbLowerBound(first, end, d - r); i < end; ++i)
      {
        float dd = ofbDepths[i] - d;
        if (dd > r)
        {
          break;
        }
        float t2 = duv2 + dd * dd;
        if (t2 > r2)
        {
          continue;
        }
        if (idw)
        {
          float t = max(sqrt(t2), 1.0e-3);
          float w = (r - t) / (r * t);
          ofbAccumulate(acc, i, w * w + 1.0e-12);
        }
        else if (t2 < closestDist2)
        {
          closest = i;
          closestDist2 = t2;
        }
      }
    }
  }
}

// Inverse-distance weighted samples of the three grids of level L around g.
ofbAccum ofbLookupIDW(int L, vec3 g)
{
  ofbAccum acc = ofbAccumInit();
  int closest = -1;
  float closestDist2 = 1.0e30;
  for (int a = 0; a < 3; ++a)
  {
    ofbGatherGrid(L, a, g, ofbRadius, true, false, acc, closest, closestDist2);
  }
  return acc;
}

// Nearest sample: the grid most aligned with the normal n first (as vtkOFB::FindSample),
// then the next most aligned grid, then the last one, then the closest sample within
// ofbRadius in the 2x2 cells nearest to g in all grids (rare: where none of the cells under
// g has a sample within one cell of depth).
// The fallbacks are loops whose condition depends on the fragment and whose trip count is a
// uniform (so that the compiler does not unroll them into branches): a software rasterizer
// (llvmpipe) runs both sides of a branch under a mask, but leaves a loop as soon as no
// fragment of the group needs it, so the common case stays cheap (3x faster on llvmpipe).
ofbAccum ofbLookupNearest(int L, vec3 g, vec3 n)
{
  ofbAccum acc = ofbAccumInit();
  vec3 an = abs(n);
  int a0 = (an.x >= an.y && an.x >= an.z) ? 0 : (an.y >= an.z ? 1 : 2);
  int b = (a0 + 1) % 3;
  int c = (a0 + 2) % 3;
  ivec3 order = an[b] >= an[c] ? ivec3(a0, b, c) : ivec3(a0, c, b);
  float dist2;
  int best = -1;
  for (int k = 0; best < 0 && k < ofbNumberOfGrids; ++k)
  {
    best = ofbNearestInGrid(L, order[k], g, dist2);
  }
  bool gather = best < 0;
  float bestDist2 = 1.0e30;
  for (int a = 0; gather && a < ofbNumberOfGrids; ++a)
  {
    ofbGatherGrid(L, a, g, ofbRadius, false, true, acc, best, bestDist2);
  }
  if (best >= 0)
  {
    ofbAccumulate(acc, best, 1.0);
  }
  return acc;
}

vec3 ofbLevelPosition(int L, vec3 g0)
{
  return g0 * ofbLevelTransform[L].w + ofbLevelTransform[L].xyz;
}

// The lookup of the current mode. lod: log2 of the fragment footprint in level-0 cells.
ofbAccum ofbLookup(vec3 g0, vec3 n, float lod)
{
#if OFB_MODE == 0
  return ofbLookupNearest(0, g0, n);
#elif OFB_MODE == 1
  return ofbLookupIDW(0, g0);
#else
  float level = clamp(lod + ofbMipmapBias, 0.0, float(ofbNumberOfLevels - 1));
  int l0 = int(floor(level));
  int l1 = min(l0 + 1, ofbNumberOfLevels - 1);
  float t = level - float(l0);
  ofbAccum a0 = ofbLookupIDW(l0, ofbLevelPosition(l0, g0));
  if (t <= 0.0 || l1 == l0)
  {
    return a0;
  }
  ofbAccum a1 = ofbLookupIDW(l1, ofbLevelPosition(l1, g0));
  // Blend the normalised results of the two levels (a level without samples here drops out).
  ofbAccum acc = ofbAccumInit();
  float w0 = a0.weight > 0.0 ? (1.0 - t) / a0.weight : 0.0;
  float w1 = a1.weight > 0.0 ? t / a1.weight : 0.0;
  acc.color = a0.color * w0 + a1.color * w1;
  acc.scalar = a0.scalar * w0 + a1.scalar * w1;
  acc.intensity = a0.intensity * w0 + a1.intensity * w1;
  acc.normal = a0.normal * w0 + a1.normal * w1;
  acc.weight = (a0.weight > 0.0 ? 1.0 - t : 0.0) + (a1.weight > 0.0 ? t : 0.0);
  return acc;
#endif
}

// Final RGBA colour of an accumulation with weight > 0.
vec4 ofbResolve(ofbAccum acc)
{
  float inv = 1.0 / acc.weight;
#ifdef OFB_SOURCE_SCALARS
  float s = clamp((acc.scalar * inv - ofbScalarRange.x) * ofbScalarRange.y, 0.0, 1.0);
  vec4 color = ofbLUT[min(int(s * float(ofbLUTSize - 1) + 0.5), ofbLUTSize - 1)];
#else
  vec4 color = acc.color * inv;
#endif
#ifdef OFB_USE_INTENSITY
  color.rgb *= mix(1.0, acc.intensity * inv, ofbIntensityWeight);
#endif
  return color;
}
