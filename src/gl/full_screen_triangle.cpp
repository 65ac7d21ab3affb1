#include "gl/full_screen_triangle.h"

#include "gl/functions.h"

namespace aurorawall::gl {

FullScreenTriangle::FullScreenTriangle() { glCreateVertexArrays(1, &vertexArray_); }

FullScreenTriangle::~FullScreenTriangle() { glDeleteVertexArrays(1, &vertexArray_); }

void FullScreenTriangle::draw() const
{
    glBindVertexArray(vertexArray_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

} // namespace aurorawall::gl
