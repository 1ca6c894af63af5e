#version 330 compatibility
// Hands the geometry shader clip-space positions, the draw's colour and
// texture coordinates 0, through the compatibility outputs.
void main( )
{
	gl_FrontColor = gl_Color;
	gl_TexCoord[0] = gl_MultiTexCoord0;
	gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
}
