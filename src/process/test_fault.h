// A GPU fault a test puts in, since llvmpipe never loses a context or reads
// back zeros: GLIMMER_TEST_FAULT=KIND:TEXT:MARKER makes the picture of a
// script whose path holds TEXT lost to a GPU reset (KIND "reset") or read
// back as zeros with no error (KIND "zeros", what an NVIDIA worker reads
// after another process's kill); KIND "stuck" (TEXT "context") makes a batch
// worker never finish making its context, as one waiting behind a process
// stuck in NVIDIA's driver did on the H200; KIND "broken" is "zeros" for
// every later drawing of that process too (a context left broken: only a
// fresh worker draws right). Once: the drawing that creates the file MARKER
// first; with MARKER empty, every time.
// Used by batch's workers (tests/cli/batch_retry_test.cpp) and render
// (tests/cli/render_lost_context_test.cpp). Unset, nothing happens.
#pragma once
#include <optional>
#include <string>

#include "image/image.h"

namespace glimmer {

class Renderer;

struct TestFault {
    std::string kind, part, marker;
};

// What GLIMMER_TEST_FAULT asks for, if anything well formed.
std::optional<TestFault> testFaultAsked();

// Whether this drawing takes the fault (MARKER: the first to make the file).
bool takesTestFault(const TestFault& f);

// After `picture` of `script` was read: why the context failed (its
// contextFailure, gl/renderer.h), with a test's fault put in; "" when it did
// not. The one question every reader of a picture asks (render, render
// --watch, batch's workers).
std::string pictureFailure(const Renderer& renderer, const std::string& script, Image& picture, std::string* refused);

}  // namespace glimmer
