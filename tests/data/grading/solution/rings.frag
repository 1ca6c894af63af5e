#version 330 compatibility
uniform float uFreq;
uniform float uTint;
in vec2 vST;
void main( )
{
    float r = length(vST - vec2(0.5));
    float ring = 0.5 + 0.5 * sin(6.2831853 * uFreq * r);
    vec3 warm = vec3(1.0, 0.6, 0.2), cool = vec3(0.1, 0.3, 0.9);
    gl_FragColor = vec4(mix(cool, warm, ring) * (0.5 + 0.5 * uTint), 1.0);
}
