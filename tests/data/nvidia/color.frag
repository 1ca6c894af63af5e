#version 330 compatibility
void main( )
{
	gl_FragColor = gl_Color;
}
