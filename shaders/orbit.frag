#version 330 compatibility

// A glowing dot that goes once round a circle every Timer period: the
// picture `glimmer render scripts/orbit.glib --frames 48 -o orbit.webp`
// animates.
uniform float Timer;     // 0 to 1 over the script's Timer period
uniform vec4  uColor;    // the dot's colour
uniform float uRadius;   // of the orbit, in texture units
uniform float uGlow;     // how far the glow reaches

in vec2 vST;

void main( )
{
    const float TWO_PI = 6.28318530718;
    vec2 centre = vec2( 0.5 ) + uRadius * vec2( cos( TWO_PI * Timer ), sin( TWO_PI * Timer ) );
    float d = distance( vST, centre );
    float core = smoothstep( 0.05, 0.04, d );
    float glow = exp( -d * d / ( uGlow * uGlow ) );
    vec3 rgb = uColor.rgb * ( core + 0.6 * glow ) + vec3( 0.02, 0.02, 0.05 );
    gl_FragColor = vec4( rgb, 1. );
}
