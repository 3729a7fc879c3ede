//VTK::System::Dec
// OFB construction, vertex stage: positions arrive in cell units of the OFB frame
// (frame origin at 0, one unit per cell), in double precision so that depths
// match the CPU sampler's; the geometry stage routes each triangle.

in dvec3 vertexCells;
out dvec3 cellsVSOutput;

void main()
{
  cellsVSOutput = vertexCells;
  gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
}
