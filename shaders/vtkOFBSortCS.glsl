//VTK::System::Dec
// Sort the samples of each cell by (depth, triangle): an insertion sort per cell,
// one invocation per cell. Cells hold few samples; any number is handled.

layout(local_size_x = 256) in;

layout(std430, binding = 1) readonly buffer Offsets
{
  uint offsets[];
};
layout(std430, binding = 2) buffer Depths
{
  float depths[];
};
layout(std430, binding = 3) buffer Triangles
{
  uint triangles[];
};
layout(std430, binding = 4) buffer FirstWeights
{
  float w1s[];
};
layout(std430, binding = 6) buffer SecondWeights
{
  float w2s[];
};

uniform uint numberOfCells;
uniform uint firstCell;

void main()
{
  uint cell = firstCell + gl_GlobalInvocationID.x;
  if (cell >= numberOfCells)
  {
    return;
  }
  uint b = offsets[cell];
  uint e = offsets[cell + 1u];
  for (uint i = b + 1u; i < e; ++i)
  {
    float d = depths[i];
    uint t = triangles[i];
    float w1 = w1s[i];
    float w2 = w2s[i];
    uint j = i;
    while (j > b && (depths[j - 1u] > d || (depths[j - 1u] == d && triangles[j - 1u] > t)))
    {
      depths[j] = depths[j - 1u];
      triangles[j] = triangles[j - 1u];
      w1s[j] = w1s[j - 1u];
      w2s[j] = w2s[j - 1u];
      --j;
    }
    depths[j] = d;
    triangles[j] = t;
    w1s[j] = w1;
    w2s[j] = w2;
  }
}
