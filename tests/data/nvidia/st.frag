#version 330 compatibility
void main( )
{
	gl_FragColor = vec4( gl_TexCoord[0].st, 1., 1. );
}
