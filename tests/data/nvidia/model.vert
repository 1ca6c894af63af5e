#version 330 compatibility
// Leaves the vertex in model coordinates: the geometry shader projects.
void main( )
{
	gl_FrontColor = gl_Color;
	gl_Position = gl_Vertex;
}
