#pragma once
// The empty vertex array for drawing fullScreenTriangleVertexShader() (core profile needs a bound
// VAO even without attributes). Vertex arrays are not shared between contexts.
#include <GL/glcorearb.h>

namespace aurorawall::gl {

class FullScreenTriangle {
public:
    FullScreenTriangle();
    FullScreenTriangle(const FullScreenTriangle&) = delete;
    FullScreenTriangle& operator=(const FullScreenTriangle&) = delete;
    ~FullScreenTriangle();

    // Draws 3 vertices with the program in use; covers the viewport.
    void draw() const;

private:
    GLuint vertexArray_ = 0;
};

} // namespace aurorawall::gl
