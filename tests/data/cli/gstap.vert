#version 330 compatibility

// New-style names, which only exist when the script says GSTAP.
void main( )
{
    gl_Position = uModelViewProjectionMatrix * aVertex;
}
