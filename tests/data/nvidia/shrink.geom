#version 330 compatibility
#extension GL_EXT_geometry_shader4: enable
layout( triangles ) in;
layout( triangle_strip, max_vertices=3 ) out;

// Each triangle shrunk towards its centre by uShrink, and pushed out along
// its normal by uExplode (in eye space; along the view for a flat model).
uniform float uShrink;
uniform float uExplode;

void main( )
{
	vec4 centre = vec4( 0. );
	for( int i = 0; i < gl_VerticesIn; i++ )
		centre += gl_PositionIn[i] / float( gl_VerticesIn );
	vec3 n = normalize( cross( gl_PositionIn[1].xyz - gl_PositionIn[0].xyz,
	                           gl_PositionIn[2].xyz - gl_PositionIn[0].xyz ) );
	for( int i = 0; i < gl_VerticesIn; i++ )
	{
		gl_TexCoord[0] = gl_TexCoordIn[i][0];
		gl_Position = centre + uShrink * ( gl_PositionIn[i] - centre ) + vec4( uExplode * n, 0. );
		EmitVertex( );
	}
	EndPrimitive( );
}
