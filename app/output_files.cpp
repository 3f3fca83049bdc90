// Files the commands write: text, and the folder of a report.

#include "commands.h"

#include "assets/image_file.h"
#include "core/cache_files.h"
#include "core/errors.h"

#include <fstream>

namespace candela::app {

void writeText(const std::string& path, const std::string& text) {
    writeFileAtomically(path, [&](std::ostream& out) { out.write(text.data(), std::streamsize(text.size())); });
}

void prepareReportFolder(const std::filesystem::path& out, std::initializer_list<const char*> files) {
    std::error_code ec;
    std::filesystem::create_directories(out, ec);
    if (ec) throw UserError(out.string() + ": cannot create the report folder: " + ec.message());
    for (const char* file : files) assets::checkWritable(out / file);
}

}  // namespace candela::app
