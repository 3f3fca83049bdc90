#include "image_writer.h"

#include <chrono>

namespace candela::app {

ImageWriter::~ImageWriter() {
    if (mPending && mPending->done.valid()) mPending->done.wait();
}

void ImageWriter::write(std::string path, Image image, OutputFileFormat format, Finished finished) {
    finish();
    std::future<double> done = std::async(std::launch::async, [path = std::move(path), image = std::move(image), format] {
        const auto start = std::chrono::steady_clock::now();
        writeImage(path, image, format);
        return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    });
    mPending.emplace(Pending{std::move(done), std::move(finished)});
}

void ImageWriter::finish() {
    if (!mPending) return;
    Pending pending = std::move(*mPending);
    mPending.reset();
    double ms = 0.0;
    std::exception_ptr error;
    try {
        ms = pending.done.get();
    } catch (...) {
        error = std::current_exception();
    }
    pending.finished(ms, error);
}

}  // namespace candela::app
