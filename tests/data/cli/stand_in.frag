#version 330 compatibility
// The picture on unit 5 where the quad is, else a solid red (the model).
uniform sampler2D uTex;
uniform bool uTextured;
in vec2 vST;
void main( )
{
    gl_FragColor = uTextured ? texture( uTex, vST ) : vec4( 1., 0., 0., 1. );
}
