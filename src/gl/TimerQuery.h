#pragma once
#include "gl/Object.h"

namespace penumbra::gl {

// GPU time of the commands between begin() and end() (GL_TIME_ELAPSED). Queries cannot nest,
// so passes are timed one after another.
class TimerQuery {
public:
    TimerQuery();
    void begin() { glBeginQuery(GL_TIME_ELAPSED, object_.id()); }
    void end() { glEndQuery(GL_TIME_ELAPSED); }
    GLuint id() const { return object_.id(); }
    // Blocks until the result is available; returns milliseconds.
    double milliseconds() const;

private:
    Object<detail::deleteQuery> object_;
};

}  // namespace penumbra::gl
