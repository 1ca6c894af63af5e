// How much one client may ask of `glimmer serve`: a token bucket per key (a
// student's or teacher's token, or an address before one is known), so a
// stuck page or a hostile script slows only itself. Sizes are bounded where
// each body is read (serve_routes.cpp: kMaxSaveBytes and the rest).
#pragma once
#include <chrono>
#include <map>
#include <mutex>
#include <string>

namespace glimmer {

class RequestLimits {
public:
    // `perSecond` requests a second on average, bursts of `burst`.
    RequestLimits(double perSecond, double burst) : rate_(perSecond), burst_(burst) {}

    // True when `key` may make one more request now (and it is counted).
    bool allow(const std::string& key) {
        const double now = std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
        std::lock_guard<std::mutex> lock(mutex_);
        if (buckets_.size() > 100000) buckets_.clear();  // bounded: a flood of addresses cannot grow it forever
        auto [it, fresh] = buckets_.try_emplace(key, Bucket{burst_, now});
        Bucket& b = it->second;
        if (!fresh) {
            b.tokens = std::min(burst_, b.tokens + (now - b.at) * rate_);
            b.at = now;
        }
        if (b.tokens < 1) return false;
        b.tokens -= 1;
        return true;
    }

private:
    struct Bucket {
        double tokens;
        double at;
    };
    double rate_, burst_;
    std::map<std::string, Bucket> buckets_;
    std::mutex mutex_;
};

}  // namespace glimmer
