#version 330 compatibility
// One typo: the sampler is uImage, the call reads uImagee. Mesa then rejects
// the texture() call and lists every overload it tried
// (tests/cli/error_cascade_test.cpp).
uniform sampler2D uImage;
in vec2 vST;
void main( )
{
    vec3 rgb = texture( uImagee, vST ).rgb;
    gl_FragColor = vec4( rgb, 1. );
}
