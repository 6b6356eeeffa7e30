#include "gl/TimerQuery.h"

namespace penumbra::gl {

TimerQuery::TimerQuery() {
    GLuint id = 0;
    glCreateQueries(GL_TIME_ELAPSED, 1, &id);
    object_ = Object<detail::deleteQuery>(id);
}

double TimerQuery::milliseconds() const {
    GLuint64 ns = 0;
    glGetQueryObjectui64v(object_.id(), GL_QUERY_RESULT, &ns);
    return static_cast<double>(ns) * 1e-6;
}

}  // namespace penumbra::gl
