#version 330 compatibility
#extension GL_EXT_geometry_shader4 : enable
layout( lines_adjacency ) in;
layout( line_strip, max_vertices = 65 ) out;

// A cubic Bezier curve through the four points of each line with adjacency.
uniform int uSegments;
varying out vec4 gColor;

void main( )
{
	vec4 p[4];
	for( int i = 0; i < gl_VerticesIn; i++ )
		p[i] = gl_PositionIn[i];
	for( int k = 0; k <= uSegments; k++ )
	{
		float t = float(k) / float(uSegments);
		float s = 1. - t;
		gl_Position = s*s*s * p[0] + 3.*s*s*t * p[1] + 3.*s*t*t * p[2] + t*t*t * p[3];
		gColor = gl_FrontColorIn[0];
		EmitVertex( );
	}
	EndPrimitive( );
}
