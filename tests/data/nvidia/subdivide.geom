#version 330 compatibility
#extension GL_EXT_gpu_shader4: enable
#extension GL_EXT_geometry_shader4: enable
// No input layout: the primitive comes from the draw (Triangles).
layout( triangle_strip, max_vertices=100 ) out;

uniform int uLevel;		// 2^uLevel rows per triangle
uniform float uRadius;

vec3 P0, E1, E2;		// a corner and the two edges from it
int N;

// Grid point (a, b) of the triangle, pushed out onto the sphere.
void Put( int a, int b )
{
	vec3 p = normalize( P0 + ( float(a) * E1 + float(b) * E2 ) / float(N) );
	gl_FrontColor = gl_FrontColorIn[0];
	gl_Position = gl_ModelViewProjectionMatrix * vec4( uRadius * p, 1. );
	EmitVertex( );
}

void main( )
{
	P0 = gl_PositionIn[0].xyz;
	E1 = ( gl_PositionIn[1] - gl_PositionIn[0] ).xyz;
	E2 = ( gl_PositionIn[2] - gl_PositionIn[0] ).xyz;
	N = 1 << uLevel;
	for( int r = 0; r < N; r++ )
	{
		// one strip between grid rows r and r+1
		for( int c = 0; c < N - r; c++ )
		{
			Put( r, c );
			Put( r + 1, c );
		}
		Put( r, N - r );
		EndPrimitive( );
	}
}
