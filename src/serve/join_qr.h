// The join address as a QR code (Debian's libqrencode): in the terminal,
// for the teacher to project at start, and as SVG on the teacher's page.
#pragma once
#include <string>

namespace glimmer {

// Two rows of modules per line in half-block characters, a quiet zone of
// two modules; light modules are drawn (a dark terminal shows dark on
// light, as a phone expects). "" when `text` cannot be encoded.
std::string qrForTerminal(const std::string& text);

// The same code as an SVG image, one unit per module.
std::string qrSvg(const std::string& text);

}  // namespace glimmer
