#pragma once
// The byte layout of the frame's messages (cluster/frame_message.h, cluster/rank_message.h): trivially
// copyable values one after the other, in the machine's own representation (every rank runs the
// same binary on the same kind of machine). Reading past the end throws std::runtime_error.
#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace aurorawall::cluster {

class ByteWriter {
public:
    template <typename T>
    void put(const T& value)
    {
        static_assert(std::is_trivially_copyable_v<T>, "only plain values travel as bytes");
        const char* p = reinterpret_cast<const char*>(&value);
        bytes_.insert(bytes_.end(), p, p + sizeof(T));
    }
    // Zero bytes up to `size` (the fixed size of a message).
    std::vector<char> padded(size_t size) const
    {
        std::vector<char> bytes = bytes_;
        bytes.resize(size, 0);
        return bytes;
    }

private:
    std::vector<char> bytes_;
};

class ByteReader {
public:
    ByteReader(const char* bytes, size_t size, std::string what) : bytes_(bytes), size_(size), what_(std::move(what)) {}

    template <typename T>
    T get()
    {
        static_assert(std::is_trivially_copyable_v<T>, "only plain values travel as bytes");
        if (at_ + sizeof(T) > size_)
            throw std::runtime_error(what_ + ": " + std::to_string(size_) + " bytes end before its content");
        T value;
        std::memcpy(&value, bytes_ + at_, sizeof(T));
        at_ += sizeof(T);
        return value;
    }

private:
    const char* bytes_;
    size_t size_;
    size_t at_ = 0;
    std::string what_;
};

} // namespace aurorawall::cluster
