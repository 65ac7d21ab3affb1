#pragma once
// A rate limit as a token bucket: it holds up to `burst` tokens, refilled at `perSecond` tokens per
// second; each line takes one, and a line that finds none is over the limit. So a client may send
// `burst` lines at once and `perSecond` lines per second on average. The time is given by the
// caller (seconds on a steady clock), so the limit is tested without waiting.
#include <algorithm>

namespace aurorawall::app::control {

class TokenBucket {
public:
    TokenBucket() = default;
    TokenBucket(double perSecond, double burst, double nowS)
        : perSecond_(perSecond), burst_(burst), tokens_(burst), lastS_(nowS)
    {
    }

    // Takes a token at time nowS; false if none is left (nothing is taken then).
    bool take(double nowS)
    {
        tokens_ = std::min(burst_, tokens_ + std::max(0.0, nowS - lastS_) * perSecond_);
        lastS_ = std::max(lastS_, nowS);
        if (tokens_ < 1.0)
            return false;
        tokens_ -= 1.0;
        return true;
    }

private:
    double perSecond_ = 0.0;
    double burst_ = 0.0;
    double tokens_ = 0.0;
    double lastS_ = 0.0;
};

} // namespace aurorawall::app::control
