#version 330 compatibility
#extension GL_EXT_geometry_shader4 : enable
// No input layout: the draw gives triangles.
layout( triangle_strip, max_vertices = 3 ) out;
void main( )
{
	for( int i = 0; i < gl_VerticesIn; i++ )
	{
		gl_Position = gl_PositionIn[i] * uScale;
		EmitVertex( );
	}
}
