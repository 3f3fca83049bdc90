#pragma once
// Writing a run's images on a worker thread: `candela render` hands each image over and goes on to
// draw the next (the next frame of a sequence, the next scene of a batch) while it is encoded and
// written. One image is written at a time, in the order handed over; handing over the next one
// first waits for the one before. See docs/outputs.md#png-encoding.

#include "candela/image.h"

#include <exception>
#include <functional>
#include <future>
#include <optional>
#include <string>

namespace candela::app {

class ImageWriter {
public:
    // What became of an image: the milliseconds its encoding and writing took, or the exception
    // writeImage threw (then 0 ms). Called on the thread that calls write() or finish(), never on
    // the worker; it may throw (out of that write() or finish()).
    using Finished = std::function<void(double encodeMs, std::exception_ptr error)>;

    ImageWriter() = default;
    ImageWriter(const ImageWriter&) = delete;
    ImageWriter& operator=(const ImageWriter&) = delete;
    // Waits for the image being written, if any, without calling its Finished.
    ~ImageWriter();

    // Finishes the image handed over before (finish()), then starts writing `image` to `path` as
    // candela::writeImage does, on the worker; `finished` is called by the next write() or finish().
    void write(std::string path, Image image, OutputFileFormat format, Finished finished);

    // Waits for the image being written, if any, and calls its Finished (once).
    void finish();

private:
    struct Pending {
        std::future<double> done;
        Finished finished;
    };
    std::optional<Pending> mPending;
};

}  // namespace candela::app
