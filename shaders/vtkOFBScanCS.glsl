//VTK::System::Dec
// Exclusive prefix sum of the cell counts into the cell offsets, in three kernels
// selected by KERNEL: 0 scans blocks of 2048 counts and stores each block's sum,
// 1 scans the block sums in one work group (in chunks, any number of blocks) and
// stores the total after them, 2 adds each block's offset to its cells.

layout(local_size_x = 256) in;

layout(std430, binding = 0) readonly buffer Counts
{
  uint counts[];
};
layout(std430, binding = 1) buffer Offsets
{
  uint offsets[];
};
layout(std430, binding = 5) buffer BlockSums
{
  uint blockSums[];
};

uniform uint numberOfValues; // cells (kernels 0, 2) or blocks (kernel 1)
uniform uint firstBlock;     // block of work group 0 (dispatches larger than the limit)

shared uint partial[256];

// Exclusive scan of one value per invocation over the work group; returns the total.
uint WorkGroupScan(inout uint value)
{
  uint id = gl_LocalInvocationID.x;
  partial[id] = value;
  barrier();
  for (uint stride = 1u; stride < 256u; stride *= 2u)
  {
    uint add = id >= stride ? partial[id - stride] : 0u;
    barrier();
    partial[id] += add;
    barrier();
  }
  uint total = partial[255];
  value = partial[id] - value;
  barrier();
  return total;
}

// Exclusive scan of 2048 values, 8 per invocation, in place; returns their total.
uint BlockScan(inout uint values[8])
{
  uint sum = 0u;
  for (uint i = 0u; i < 8u; ++i)
  {
    uint value = values[i];
    values[i] = sum;
    sum += value;
  }
  uint prefix = sum;
  uint total = WorkGroupScan(prefix);
  for (uint i = 0u; i < 8u; ++i)
  {
    values[i] += prefix;
  }
  return total;
}

void main()
{
  uint id = gl_LocalInvocationID.x;
#if KERNEL == 0
  uint block = firstBlock + gl_WorkGroupID.x;
  uint first = block * 2048u + id * 8u;
  uint values[8];
  for (uint i = 0u; i < 8u; ++i)
  {
    values[i] = (first + i < numberOfValues) ? counts[first + i] : 0u;
  }
  uint total = BlockScan(values);
  for (uint i = 0u; i < 8u; ++i)
  {
    if (first + i < numberOfValues)
    {
      offsets[first + i] = values[i];
    }
  }
  if (id == 0u)
  {
    blockSums[block] = total;
  }
#elif KERNEL == 1
  uint carry = 0u;
  for (uint chunk = 0u; chunk < numberOfValues; chunk += 2048u)
  {
    uint first = chunk + id * 8u;
    uint values[8];
    for (uint i = 0u; i < 8u; ++i)
    {
      values[i] = (first + i < numberOfValues) ? blockSums[first + i] : 0u;
    }
    uint total = BlockScan(values);
    for (uint i = 0u; i < 8u; ++i)
    {
      if (first + i < numberOfValues)
      {
        blockSums[first + i] = carry + values[i];
      }
    }
    carry += total;
    barrier();
  }
  if (id == 0u)
  {
    blockSums[numberOfValues] = carry;
  }
#else
  uint block = firstBlock + gl_WorkGroupID.x;
  uint add = blockSums[block];
  uint first = block * 2048u + id * 8u;
  for (uint i = 0u; i < 8u; ++i)
  {
    if (first + i < numberOfValues)
    {
      offsets[first + i] += add;
    }
  }
#endif
}
