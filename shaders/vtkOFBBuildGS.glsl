//VTK::System::Dec
// OFB construction, geometry stage: each triangle goes to the grid of the axis
// closest to its face normal (viewport gl_ViewportIndex = axis). Grid a spans
// axes u = (a+1)%3 and v = (a+2)%3; window coordinates are cell units, so pixel
// centres are cell centres. The triangle's depth plane (double precision) and
// barycentric functions go to the fragment stage relative to a cell corner near
// the first vertex, so that the fragment stage evaluates them precisely.
// Vertices are snapped to the 1/256-cell lattice of the CPU sampler, and the
// viewport side is a power of two, so the rasterizer sees exactly the CPU's
// vertices: both backends cover the same cell centres.

layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;

in dvec3 cellsVSOutput[];

uniform double viewportSize; // power of two >= every grid side: exact NDC mapping

flat out int gridAxis;
flat out uint triangleId;
flat out ivec2 corner;     // integer cell corner near vertex 0
flat out dvec3 depthPlane; // depth (cells) at the corner, and its u and v gradients
flat out vec2 vertex0;     // vertex 0 relative to the corner (cells)
flat out vec4 baryCoeffs;  // w1 = x * du + y * dv, w2 = z * du + w * dv

void main()
{
  dvec3 p0 = cellsVSOutput[0];
  dvec3 p1 = cellsVSOutput[1];
  dvec3 p2 = cellsVSOutput[2];
  dvec3 n = abs(cross(p1 - p0, p2 - p0));
  int a = 0;
  if (n.y > n[a])
  {
    a = 1;
  }
  if (n.z > n[a])
  {
    a = 2;
  }
  int u = (a + 1) % 3;
  int v = (a + 2) % 3;
  dvec2 q0 = dvec2(p0[u], p0[v]);
  dvec2 e1 = dvec2(p1[u], p1[v]) - q0;
  dvec2 e2 = dvec2(p2[u], p2[v]) - q0;
  double denom = e1.x * e2.y - e1.y * e2.x;
  if (denom == 0.0)
  {
    return;
  }
  double inv = 1.0 / denom;
  dvec4 coeffs = dvec4(e2.y * inv, -e2.x * inv, -e1.y * inv, e1.x * inv);
  double dz1 = p1[a] - p0[a];
  double dz2 = p2[a] - p0[a];
  // Depth gradients: z = z0 + w1 * dz1 + w2 * dz2 with w linear in (u, v).
  dvec2 gradient = dvec2(coeffs.x * dz1 + coeffs.z * dz2, coeffs.y * dz1 + coeffs.w * dz2);
  ivec2 c = ivec2(floor(q0));
  dvec2 offset = q0 - dvec2(c);
  double zCorner = p0[a] - dot(gradient, offset);
  dvec3 p[3] = dvec3[3](p0, p1, p2);
  for (int i = 0; i < 3; ++i)
  {
    gridAxis = a;
    triangleId = uint(gl_PrimitiveIDIn);
    corner = c;
    depthPlane = dvec3(zCorner, gradient);
    vertex0 = vec2(offset);
    baryCoeffs = vec4(coeffs);
    gl_ViewportIndex = a;
    dvec2 snapped = floor((dvec2(p[i][u], p[i][v]) - 0.5) * 256.0 + 0.5) / 256.0 + 0.5;
    gl_Position = vec4(vec2(2.0 * snapped / viewportSize - 1.0), 0.0, 1.0);
    EmitVertex();
  }
  EndPrimitive();
}
