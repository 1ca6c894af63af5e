#version 330 compatibility
#extension GL_EXT_gpu_shader4: enable
#extension GL_EXT_geometry_shader4: enable
layout( triangles_adjacency ) in;
layout( line_strip, max_vertices=200 ) out;

// Silhouette edges: an edge of a triangle facing the eye whose neighbour
// across it faces away. Vertices 0 2 4 are the triangle; 1 3 5 the far
// corners of its neighbours (not gl_PositionIn[ 6 ], there is none).

float Area2( int a, int b, int c )	// twice the signed screen area of a b c
{
	vec2 A = gl_PositionIn[a].xy / gl_PositionIn[a].w;
	vec2 B = gl_PositionIn[b].xy / gl_PositionIn[b].w;
	vec2 C = gl_PositionIn[ c ].xy / gl_PositionIn[ c ].w;
	return ( B.x - A.x ) * ( C.y - A.y ) - ( B.y - A.y ) * ( C.x - A.x );
}

void Edge( int a, int b )
{
	gl_FrontColor = gl_FrontColorIn[a];
	gl_Position = gl_PositionIn[a];
	EmitVertex( );
	gl_FrontColor = gl_FrontColorIn[b];
	gl_Position = gl_PositionIn[b];
	EmitVertex( );
	EndPrimitive( );
}

void main( )
{
	if( Area2( 0, 2, 4 ) <= 0. )
		return;
	if( Area2( 0, 1, 2 ) <= 0. )	Edge( 0, 2 );
	if( Area2( 2, 3, 4 ) <= 0. )	Edge( 2, 4 );
	if( Area2( 4, 5, 0 ) <= 0. )	Edge( 4, 0 );
}
