// vtkOFBLookupFS.glsl: declarations and functions that vtkOFBPolyDataMapper inserts into
// the fragment shader of vtkOpenGLPolyDataMapper (with the colour declarations) to colour every
// fragment from the samples of a vtkOFB (paper "Sample-based Surface Coloring", 4.1-4.2).
//
// The mapper defines before this text:
//   OFB_LOOKUP_NEAREST, OFB_LOOKUP_INVERSE_DISTANCE, OFB_LOOKUP_MIPMAPPED,
//   OFB_LOOKUP_NEAREST_MIPMAPPED, OFB_LOOKUP_SMOOTH
//                       the lookup modes (vtkOFBPolyDataMapper::LookupModes): nearest
//                       sample, inverse-distance weighting, mipmapped IDW, nearest sample
//                       in the level nearest to the fragment's footprint, smooth surface
//                       interpolation blended over the levels around the footprint
//   OFB_LOOKUP_MODE     the mode of this shader, one of those (another is an #error)
//   OFB_MAX_LEVELS      size of the per-level uniform arrays
//   OFB_SOURCE_SCALARS  colour from a float sample attribute through a lookup table, else paint
//   OFB_USE_INTENSITY   a float sample array (the LIC) combines with the colour
//   OFB_LIC_MODE        how: 0 blend (by ofbLICIntensity), 1 map (multiply, ofbMapModeBias)
//   OFB_ENHANCE_COLOR   the lightness of the final colour is stretched (VTK surface LIC's
//                       colour contrast enhancement)
//   OFB_USE_NORMALS     painted normals replace the interpolated normal for shading
//   OFB_DEEP_CELLS      some cell holds many samples: binary searches before the linear scans
//   OFB_LEVEL_INTENSITY the intensity of every level is computed on that level (a LIC per
//                       level): independent textures, blended keeping their contrast
//   OFB_FLOW_FILTER     (Smooth, with OFB_USE_INTENSITY) level 0's flow directions are
//                       uploaded: close up, the intensity is averaged along the flow
// and enables GL_ARB_shader_bit_encoding and (where offered) GL_ARB_ES3_1_compatibility.
//
// Units: every position here is in cells of the level being read, measured from the
// low corner of that level's frame; depths are uploaded in the same unit.
// Storage (std430 shader storage blocks, bound by the mapper):
//   ofbOffsets  per level, one prefix sum over the cells of grids X, Y, Z (plus one entry),
//               relative to the level's first sample
//   ofbSamples  per sample, two words: x the depth along the grid axis (float bits; sorted
//               within a cell), y the colour attribute next to it, so that one read gives
//               both: RGBA8 packed in a uint (red in the low byte), or with
//               OFB_SOURCE_SCALARS the scalar (float bits)
//   ofbIntensity per sample a byte (the value in [0, 1] times 255, four to a uint; each
//               level starts at a multiple of 4 samples); ofbNormals three floats per sample
//   ofbFlow     of level 0 only, per sample the unit vector of the field the LIC follows:
//               x, y, z times 511 as 10-bit two's complement integers at bits 0, 10, 20
//               (0: no field there)
//   ofbLUT      the lookup table sampled at equal steps over the scalar range
//
// Performance notes (Mesa llvmpipe, where these shaders run on the CPU): a fragment shader
// runs on groups of 8 fragments, most of them partly covered when triangles are small; both
// sides of every branch execute under a mask, a loop runs its body at least once and then
// until no fragment of the group needs another iteration, and every storage-buffer read
// visits the 8 lanes one by one. So the code that a fragment rarely needs is not skipped,
// it costs its full length every time: the lookups below keep it short, as loops whose
// first iteration is the common case, and read as few words as possible. Helper lanes
// (uncovered fragments that only feed derivatives) leave the loops after the first
// iteration: their extrapolated positions would otherwise keep a group in the fallbacks.

layout(std430) readonly buffer ofbOffsetsBlock { uint ofbOffsets[]; };
layout(std430) readonly buffer ofbSamplesBlock { uvec2 ofbSamples[]; };
#ifdef OFB_SOURCE_SCALARS
layout(std430) readonly buffer ofbLUTBlock { vec4 ofbLUT[]; };
uniform vec2 ofbScalarRange; // x: low end, y: 1 / (high - low)
uniform int ofbLUTSize;
#endif
#ifdef OFB_USE_INTENSITY
// one byte a sample, four to a word: value / 255
layout(std430) readonly buffer ofbIntensityBlock { uint ofbIntensity[]; };
uniform float ofbIntensityWeight; // map mode: strength of the multiplication
uniform float ofbLICIntensity;    // blend mode: the LIC's share
uniform float ofbMapModeBias;     // map mode: added to the LIC
#ifdef OFB_LEVEL_INTENSITY
uniform float ofbIntensityMean;   // the mean of level 0's intensity
#endif
#endif
#ifdef OFB_FLOW_FILTER
layout(std430) readonly buffer ofbFlowBlock { uint ofbFlow[]; };
uniform float ofbFlowOffsetMax; // the longest offset of the side lookups, in cells (2)
#endif
#ifdef OFB_ENHANCE_COLOR
uniform vec2 ofbLightnessStretch; // x: low end m, y: 1 / (M - m), 0: none

// HSL lightness, and the colour with another lightness, hue and saturation kept (as
// Filters/vtkOFBColorSpace.h).
float ofbLightness(vec3 c)
{
  return 0.5 * (max(c.r, max(c.g, c.b)) + min(c.r, min(c.g, c.b)));
}

vec3 ofbWithLightness(vec3 c, float l)
{
  float high = max(c.r, max(c.g, c.b));
  float low = min(c.r, min(c.g, c.b));
  float chroma = high - low;
  float room = 1.0 - abs(high + low - 1.0);
  if (!(chroma > 0.0) || !(room > 0.0))
  {
    return vec3(l);
  }
  float chroma2 = (1.0 - abs(2.0 * l - 1.0)) * min(1.0, chroma / room);
  return clamp(vec3(l) + chroma2 * ((c - low) / chroma - 0.5), 0.0, 1.0);
}
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
// 15, the cells a Nearest lookup may visit: a uniform, so that the compiler keeps the loop
// (unrolled, its rare iterations would run for every fragment)
uniform int ofbNearestVisits;

in vec3 ofbGridVSOutput; // level-0 grid position of the fragment, in cells

#if defined(GL_ARB_ES3_1_compatibility) || __VERSION__ >= 450
#define OFB_HELPER_INVOCATION gl_HelperInvocation
#else
#define OFB_HELPER_INVOCATION false
#endif

struct ofbAccum
{
  vec4 color;
  float scalar;
  float intensity;
  vec3 normal;
  float weight;
#ifdef OFB_FLOW_FILTER
  vec3 flow; // the weighted flow directions (the centre lookup of level 0 only)
#endif
};

ofbAccum ofbAccumInit()
{
  ofbAccum acc;
  acc.color = vec4(0.0);
  acc.scalar = 0.0;
  acc.intensity = 0.0;
  acc.normal = vec3(0.0);
  acc.weight = 0.0;
#ifdef OFB_FLOW_FILTER
  acc.flow = vec3(0.0);
#endif
  return acc;
}

vec4 ofbUnpackColor(uint c)
{
  return vec4(float(c & 0xFFu), float((c >> 8u) & 0xFFu), float((c >> 16u) & 0xFFu),
           float(c >> 24u)) / 255.0;
}

// Add sample i, whose colour attribute (ofbSamples[i].y) is attr, whose intensity word
// (ofbIntensity[i >> 2], where there is one) is lic and whose painted normal (where the
// mapper uses them) is normal, with weight w.
void ofbAccumulateRead(inout ofbAccum acc, int i, uint attr, uint lic, vec3 normal, float w)
{
#ifdef OFB_SOURCE_SCALARS
  acc.scalar += w * uintBitsToFloat(attr);
#else
  // Colours premultiplied by alpha: a transparent sample adds no colour, only coverage.
  vec4 c = ofbUnpackColor(attr);
  acc.color += w * vec4(c.rgb * c.a, c.a);
#endif
#ifdef OFB_USE_INTENSITY
  acc.intensity += w * float((lic >> (8u * uint(i & 3))) & 0xFFu) * (1.0 / 255.0);
#endif
#ifdef OFB_USE_NORMALS
  acc.normal += w * normal;
#endif
  acc.weight += w;
}

// The intensity word of sample i, 0 without intensity.
uint ofbIntensityWord(int i)
{
#ifdef OFB_USE_INTENSITY
  return ofbIntensity[i >> 2];
#else
  return 0u;
#endif
}

// The painted normal of sample i, 0 without painted normals.
vec3 ofbPaintedNormal(int i)
{
#ifdef OFB_USE_NORMALS
  return vec3(ofbNormals[3 * i], ofbNormals[3 * i + 1], ofbNormals[3 * i + 2]);
#else
  return vec3(0.0);
#endif
}

// Add sample i, whose colour attribute (ofbSamples[i].y) is attr, with weight w.
void ofbAccumulate(inout ofbAccum acc, int i, uint attr, float w)
{
  ofbAccumulateRead(acc, i, attr, ofbIntensityWord(i), ofbPaintedNormal(i), w);
}

// Grid a of level L: g as (u, v, depth) in that grid, its cells along u and v, and the
// ofbOffsets entry of its first cell (selects, no dynamic indexing of vectors).
void ofbGridFrame(int L, int a, vec3 g, out vec3 uvd, out ivec2 n, out int cellBase)
{
  uvd = a == 0 ? g.yzx : (a == 1 ? g.zxy : g.xyz);
  ivec3 dims = ivec3(ofbLevelDims[3 * L], ofbLevelDims[3 * L + 1], ofbLevelDims[3 * L + 2]);
  n = a == 0 ? dims.yz : (a == 1 ? dims.zx : dims.xy);
  cellBase = ofbLevelCellBase[3 * L + a];
}

// Sample range [first, end) of cell c of a grid of level L with n cells whose first cell is
// entry cellBase of ofbOffsets; empty outside the grid or without `use`. No branch.
void ofbCellRange(int L, int cellBase, ivec2 n, ivec2 c, bool use, out int first, out int end)
{
  bool inside = use && all(greaterThanEqual(c, ivec2(0))) && all(lessThan(c, n));
  int cell = cellBase + (inside ? c.y * n.x + c.x : 0);
  first = ofbLevelSampleBase[L] + int(ofbOffsets[cell]);
  end = inside ? ofbLevelSampleBase[L] + int(ofbOffsets[cell + 1]) : first;
}

// Where the scan of [first, end) for depths >= low starts: with OFB_DEEP_CELLS the first
// sample at depth >= low (binary search), else `first` (a cell holds a few samples, and
// a linear scan that stops early reads fewer words than a search and its checks).
int ofbScanStart(int first, int end, float low)
{
#ifdef OFB_DEEP_CELLS
  int hi = end;
  while (first < hi)
  {
    int mid = (first + hi) >> 1;
    if (uintBitsToFloat(ofbSamples[mid].x) < low)
    {
      first = mid + 1;
    }
    else
    {
      hi = mid;
    }
  }
#endif
  return first;
}

// Nearest sample (vtkOFB::FindSample, paper 4.1, then fallbacks): the closest sample in
// depth within one cell, in the cell under g of the grid most aligned with the normal n
// (the grid that the sampler routed the fragment's triangle to); where there is none, the
// same in the next most aligned grid, then in the last one; where still none (along the
// borders between the regions of the grids), the closest sample within ofbRadius in the
// 2x2 cells nearest to g of all three grids, X first. Ties go to the lower depth, then to
// the earlier cell. The 15 cell visits are the iterations of one loop whose first
// iteration is the common case (see the performance notes above).
ofbAccum ofbLookupNearest(int L, vec3 g, vec3 n)
{
  vec3 an = abs(n);
  int a0 = (an.x >= an.y && an.x >= an.z) ? 0 : (an.y >= an.z ? 1 : 2);
  int b = a0 == 2 ? 0 : a0 + 1;
  int c = a0 == 0 ? 2 : a0 - 1;
  float nb = b == 0 ? an.x : (b == 1 ? an.y : an.z);
  float nc = c == 0 ? an.x : (c == 1 ? an.y : an.z);
  int a1 = nb >= nc ? b : c;
  int a2 = nb >= nc ? c : b;
  float r2 = ofbRadius * ofbRadius;
  int best = -1;
  float bestScore = 0.0;
  uint bestAttr = 0u;
  uint bestLic = 0u;
  vec3 bestNormal = vec3(0.0);
  for (int k = 0; k < ofbNearestVisits; ++k)
  {
    // k < 3: the cell under g in grids a0, a1, a2, by depth within one cell;
    // k >= 3: cell (k - 3) & 3 of the 2x2 nearest cells of grid (k - 3) >> 2, by distance.
    bool near = k >= 3;
    int j = k - 3;
    int a = k == 0 ? a0 : (k == 1 ? a1 : (k == 2 ? a2 : j >> 2));
    vec3 uvd;
    ivec2 cells;
    int cellBase;
    ofbGridFrame(L, a, g, uvd, cells, cellBase);
    ivec2 cell = near ? ivec2(floor(uvd.xy - 0.5)) + ivec2(j & 1, (j >> 1) & 1)
                      : ivec2(floor(uvd.xy));
    vec2 duv = uvd.xy - (vec2(cell) + 0.5);
    float duv2 = near ? dot(duv, duv) : 0.0;
    float limit = near ? r2 : 1.0;
    int first;
    int end;
    ofbCellRange(L, cellBase, cells, cell, duv2 <= limit, first, end);
    // Depths are sorted: past the first sample at or above g, the distance only grows.
    for (int i = ofbScanStart(first, end, uvd.z - (near ? ofbRadius : 1.0)); i < end; ++i)
    {
      uvec2 s = ofbSamples[i];
      // The intensity and painted normal read with the sample, not after the search:
      // the memory accesses overlap instead of following each other.
      uint lic = ofbIntensityWord(i);
      vec3 normal = ofbPaintedNormal(i);
      float dd = uintBitsToFloat(s.x) - uvd.z;
      float score = duv2 + dd * dd;
      if (score <= limit && (best < 0 || score < bestScore))
      {
        best = i;
        bestScore = score;
        bestAttr = s.y;
        bestLic = lic;
        bestNormal = normal;
      }
      if (dd >= 0.0)
      {
        break;
      }
    }
    if (OFB_HELPER_INVOCATION || (k < 3 && best >= 0))
    {
      break;
    }
  }
  ofbAccum acc = ofbAccumInit();
  if (best >= 0)
  {
    ofbAccumulateRead(acc, best, bestAttr, bestLic, bestNormal, 1.0);
  }
  return acc;
}

// Inverse-distance weighted samples within ofbRadius of g (level L units) in the 3x3 cells
// around the cell under g in all three grids (paper 4.2), with Shepard weights
// ((r - t) / (r t))^2; grids X, Y, Z in turn, rows of cells v then u, samples by depth.
ofbAccum ofbLookupIDW(int L, vec3 g)
{
  ofbAccum acc = ofbAccumInit();
  float r = ofbRadius;
  float r2 = r * r;
  for (int k = 0; k < 27; ++k)
  {
    int a = k >= 18 ? 2 : (k >= 9 ? 1 : 0);
    int j = k - 9 * a;
    int jv = j >= 6 ? 1 : (j >= 3 ? 0 : -1);
    int ju = j - 3 * jv - 4;
    vec3 uvd;
    ivec2 cells;
    int cellBase;
    ofbGridFrame(L, a, g, uvd, cells, cellBase);
    ivec2 cell = ivec2(floor(uvd.xy)) + ivec2(ju, jv);
    vec2 duv = uvd.xy - (vec2(cell) + 0.5);
    float duv2 = dot(duv, duv);
    int first;
    int end;
    ofbCellRange(L, cellBase, cells, cell, duv2 <= r2, first, end);
    for (int i = ofbScanStart(first, end, uvd.z - r); i < end; ++i)
    {
      uvec2 s = ofbSamples[i];
      float dd = uintBitsToFloat(s.x) - uvd.z;
      if (dd > r)
      {
        break;
      }
      float t2 = duv2 + dd * dd;
      if (t2 <= r2)
      {
        float t = max(sqrt(t2), 1.0e-3);
        float w = (r - t) / (r * t);
        ofbAccumulate(acc, i, s.y, w * w + 1.0e-12);
      }
    }
  }
  return acc;
}

// Smooth interpolation along the surface (level L units): in each of the three grids, the
// samples of the 2x2 cells whose centres are nearest to g, weighted by the tents
// (1 - |du|)(1 - |dv|) of their in-plane offsets (bilinear interpolation where the surface
// lies in one grid's region: the weights of a grid sum to 1), times their agreement with
// the fragment's tangent plane (n, the face normal): 1 within half a cell of the plane, 0
// from one cell (the other side of a thin sheet, another sheet in the same cell) or beyond
// two cells in depth. Every weight is continuous in g and vanishes before its cell leaves
// the 2x2, so the values are continuous across cell borders and across the borders
// between the grids' regions (no cell blocks where a cell covers many pixels). Where no
// sample has weight, the nearest sample. With `flow` (level 0, OFB_FLOW_FILTER), the
// samples' flow directions are accumulated with the same weights.
ofbAccum ofbLookupSmooth(int L, vec3 g, vec3 n, bool flow)
{
  ofbAccum acc = ofbAccumInit();
  float nl = length(n);
  vec3 nn = nl > 0.0 ? n / nl : vec3(0.0);
  for (int k = 0; k < 12; ++k)
  {
    int a = k >> 2;
    int j = k & 3;
    vec3 uvd;
    ivec2 cells;
    int cellBase;
    ofbGridFrame(L, a, g, uvd, cells, cellBase);
    vec3 nuvd = a == 0 ? nn.yzx : (a == 1 ? nn.zxy : nn.xyz);
    ivec2 cell = ivec2(floor(uvd.xy - 0.5)) + ivec2(j & 1, j >> 1);
    vec2 duv = (vec2(cell) + 0.5) - uvd.xy;
    vec2 tent = max(vec2(1.0) - abs(duv), vec2(0.0));
    float wuv = tent.x * tent.y;
    int first;
    int end;
    ofbCellRange(L, cellBase, cells, cell, wuv > 0.0, first, end);
    for (int i = ofbScanStart(first, end, uvd.z - 2.0); i < end; ++i)
    {
      uvec2 s = ofbSamples[i];
      float dd = uintBitsToFloat(s.x) - uvd.z;
      if (dd > 2.0)
      {
        break;
      }
      float h = abs(dot(vec3(duv, dd), nuvd));
      float w = wuv * (1.0 - smoothstep(0.5, 1.0, h));
      if (w > 0.0)
      {
        ofbAccumulate(acc, i, s.y, w);
#ifdef OFB_FLOW_FILTER
        if (flow)
        {
          uint f = ofbFlow[i];
          acc.flow += w *
            vec3(ivec3(int(f << 22u), int(f << 12u), int(f << 2u)) >> 22) * (1.0 / 511.0);
        }
#endif
      }
    }
  }
  if (!(acc.weight > 0.0) && !OFB_HELPER_INVOCATION)
  {
    acc = ofbLookupNearest(L, g, n);
  }
  return acc;
}

#ifdef OFB_FLOW_FILTER
// The flow-aligned filter of a LIC close up (level 0): the intensity of `acc` (the Smooth
// lookup at g, with its flow) replaced by the average of the Smooth lookups at g - d, g and
// g + d with weights 1/4, 1/2, 1/4, d along the flow projected onto the tangent plane
// (normal n). The bilinear interpolation of a streak at an angle to the grid modulates it
// along its length: a unit step along the streak (tangent t) crosses |t_u| and |t_v| cells
// of the grid plane (u, v) of the samples, so the modulation has periods 1 / |t_u| and
// 1 / |t_v| (beads of 1.41 cells on a diagonal, stair steps of 1 / sin of the angle near
// an axis), the longer one the stronger. The average cancels a period of 2 |d|: |d| is
// half the longer period, 0.5 / min(|t_u|, |t_v|), at most ofbFlowOffsetMax, blended over
// the three grids by the normal (so that it is continuous where the grid changes). Along
// the flow only, the streaks' profile across is kept. `strength` in [0, 1] blends it in;
// it fades out where the flow directions around g disagree (their mean is short: about a
// critical point).
ofbAccum ofbFlowFilter(ofbAccum acc, vec3 g, vec3 n, float strength)
{
  if (!(acc.weight > 0.0))
  {
    return acc;
  }
  float nl = length(n);
  vec3 nn = nl > 0.0 ? n / nl : vec3(0.0);
  vec3 m = acc.flow / acc.weight;
  vec3 t = m - dot(m, nn) * nn;
  float coherence = length(t);
  float k = strength * smoothstep(0.25, 0.5, coherence);
  if (!(k > 0.0))
  {
    return acc;
  }
  vec3 at = abs(t) / coherence;
  // The shorter in-plane component of each grid (X: y z, Y: z x, Z: x y), weighted by how
  // much each grid holds the surface here.
  vec3 shortest = vec3(min(at.y, at.z), min(at.z, at.x), min(at.x, at.y));
  vec3 halfPeriod = min(vec3(0.5) / max(shortest, vec3(1.0e-3)), vec3(ofbFlowOffsetMax));
  vec3 an2 = nn * nn;
  vec3 share = an2 * an2;
  float offset = dot(share, halfPeriod) / max(dot(share, vec3(1.0)), 1.0e-6);
  vec3 d = t * (offset / coherence);
  float centre = acc.intensity / acc.weight;
  float filtered = 0.5 * centre;
  // One loop over the two sides: one copy of the lookup in the compiled shader.
  for (int side = 0; side < 2; ++side)
  {
    ofbAccum s = ofbLookupSmooth(0, side == 0 ? g + d : g - d, n, false);
    filtered += 0.25 * (s.weight > 0.0 ? s.intensity / s.weight : centre);
  }
  acc.intensity = mix(centre, filtered, k) * acc.weight;
  return acc;
}
#endif

// The filtered lookup of one level of the blended modes: smooth, else inverse distance.
ofbAccum ofbLookupLevel(int L, vec3 g, vec3 n)
{
#if OFB_LOOKUP_MODE == OFB_LOOKUP_SMOOTH
  return ofbLookupSmooth(L, g, n, false);
#else
  return ofbLookupIDW(L, g);
#endif
}

vec3 ofbLevelPosition(int L, vec3 g0)
{
  return g0 * ofbLevelTransform[L].w + ofbLevelTransform[L].xyz;
}

// The lookup of the current mode. lod: log2 of the fragment footprint in level-0 cells.
ofbAccum ofbLookup(vec3 g0, vec3 n, float lod)
{
#if OFB_LOOKUP_MODE == OFB_LOOKUP_NEAREST
  return ofbLookupNearest(0, g0, n);
#elif OFB_LOOKUP_MODE == OFB_LOOKUP_INVERSE_DISTANCE
  return ofbLookupIDW(0, g0);
#elif OFB_LOOKUP_MODE == OFB_LOOKUP_NEAREST_MIPMAPPED
  // The level whose cells are nearest to the footprint (level 0 below 1.41 cells).
  int L = clamp(int(floor(lod + ofbMipmapBias + 0.5)), 0, ofbNumberOfLevels - 1);
  return ofbLookupNearest(L, ofbLevelPosition(L, g0), n);
#elif OFB_LOOKUP_MODE == OFB_LOOKUP_MIPMAPPED || OFB_LOOKUP_MODE == OFB_LOOKUP_SMOOTH
  // The two levels around the footprint, blended by where it lies between them (level 0
  // alone where a level-0 cell covers a pixel or more): no line where the level changes.
  float level = clamp(lod + ofbMipmapBias, 0.0, float(ofbNumberOfLevels - 1));
  int l0 = int(floor(level));
  int l1 = min(l0 + 1, ofbNumberOfLevels - 1);
  float t = level - float(l0);
#if OFB_LOOKUP_MODE == OFB_LOOKUP_SMOOTH && defined(OFB_FLOW_FILTER)
  // Close up, the flow-aligned filter on level 0: in full where a level-0 cell covers 1.4
  // pixels or more, fading out to none at 0.7 pixels. Views where no cell covers 0.7
  // pixels use the shader without it (vtkOFBPolyDataMapper::FlowFilterInView).
  bool flow = l0 == 0 && lod < 0.5;
  ofbAccum a0 = ofbLookupSmooth(l0, ofbLevelPosition(l0, g0), n, flow);
  if (flow)
  {
    a0 = ofbFlowFilter(a0, g0, n, clamp(0.5 - lod, 0.0, 1.0));
  }
#else
  ofbAccum a0 = ofbLookupLevel(l0, ofbLevelPosition(l0, g0), n);
#endif
  if (t <= 0.0 || l1 == l0)
  {
    return a0;
  }
  ofbAccum a1 = ofbLookupLevel(l1, ofbLevelPosition(l1, g0), n);
  // Blend the normalised results of the two levels (a level without samples here drops out).
  ofbAccum acc = ofbAccumInit();
  float w0 = a0.weight > 0.0 ? (1.0 - t) / a0.weight : 0.0;
  float w1 = a1.weight > 0.0 ? t / a1.weight : 0.0;
  acc.color = a0.color * w0 + a1.color * w1;
  acc.scalar = a0.scalar * w0 + a1.scalar * w1;
  acc.intensity = a0.intensity * w0 + a1.intensity * w1;
  acc.normal = a0.normal * w0 + a1.normal * w1;
  acc.weight = (a0.weight > 0.0 ? 1.0 - t : 0.0) + (a1.weight > 0.0 ? t : 0.0);
#if defined(OFB_USE_INTENSITY) && defined(OFB_LEVEL_INTENSITY)
  // Two independent textures mixed: their deviations from the mean scaled back to the
  // variance of one, so that the streaks keep their contrast between the levels.
  if (a0.weight > 0.0 && a1.weight > 0.0)
  {
    float keep = inversesqrt((1.0 - t) * (1.0 - t) + t * t);
    acc.intensity = ofbIntensityMean + (acc.intensity - ofbIntensityMean) * keep;
  }
#endif
  return acc;
#else
#error unknown lookup mode (OFB_LOOKUP_MODE)
#endif
}

// Final RGBA colour (not premultiplied) of an accumulation with weight > 0.
vec4 ofbResolve(ofbAccum acc)
{
  float inv = 1.0 / acc.weight;
#ifdef OFB_SOURCE_SCALARS
  float s = clamp((acc.scalar * inv - ofbScalarRange.x) * ofbScalarRange.y, 0.0, 1.0);
  vec4 color = ofbLUT[min(int(s * float(ofbLUTSize - 1) + 0.5), ofbLUTSize - 1)];
#else
  vec4 color = acc.color * inv;
  color.rgb = color.a > 0.0 ? color.rgb / color.a : vec3(0.0);
#endif
#ifdef OFB_USE_INTENSITY
  // The LIC combined as vtkSurfaceLICInterface does: blend, or map (multiply).
  float lic = acc.intensity * inv;
#if OFB_LIC_MODE == 0
#ifdef OFB_ENHANCE_COLOR
  color.rgb = mix(color.rgb, vec3(lic), ofbLICIntensity);
#endif
  // Without colour contrast, blend mode mixes the LIC after the lighting (ofbBlendLIC),
  // as vtkSurfaceLICInterface does: the LIC's grey is not shaded.
#else
  color.rgb *= mix(1.0, clamp(lic + ofbMapModeBias, 0.0, 1.0), ofbIntensityWeight);
#endif
#endif
#ifdef OFB_ENHANCE_COLOR
  if (ofbLightnessStretch.y > 0.0)
  {
    color.rgb = ofbWithLightness(color.rgb,
      clamp((ofbLightness(color.rgb) - ofbLightnessStretch.x) * ofbLightnessStretch.y, 0.0, 1.0));
  }
#endif
  return color;
}

// Blend mode without colour contrast: the lit colour mixed with the unlit LIC grey.
vec3 ofbBlendLIC(vec3 lit, ofbAccum acc)
{
#if defined(OFB_USE_INTENSITY) && OFB_LIC_MODE == 0 && !defined(OFB_ENHANCE_COLOR)
  return acc.weight > 0.0 ? mix(lit, vec3(acc.intensity / acc.weight), ofbLICIntensity) : lit;
#else
  return lit;
#endif
}
