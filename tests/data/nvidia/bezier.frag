#version 330 compatibility
in vec4 gColor;
void main( )
{
	gl_FragColor = gColor;
}
