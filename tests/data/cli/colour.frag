#version 330 compatibility

uniform vec4 uColor;
uniform vec3 uOffset;

void main( )
{
    gl_FragColor = vec4( uColor.rgb + uOffset, uColor.a );
}
