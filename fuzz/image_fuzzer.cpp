// Fuzzes the image decoders: clr::load_image on a file holding the input.
//
// One target serves the four decoder paths. load_image() chooses PNG, JPEG, PPM P3 or PPM P6
// from the file's first bytes, so what steers a run to one decoder is its seed corpus (and
// dictionary): scripts/fuzz.sh runs this binary once per format with that format's seeds.
// Mutations that change the magic bytes simply cross over to another decoder, which is also
// input that clrender must survive.
//
// The contract under test (image_loader.h): any bytes either decode to an 8-bit RGBA image
// of consistent size or are rejected with a clr::ImageError whose reason is one printable
// line (the scene loader quotes it in its error). Anything else is a bug.
#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>
#include <typeinfo>

#include "fuzz_support.h"
#include "scene/image_loader.h"

namespace {

// The input goes through a real file, as in clrender, so that the file-reading code is
// under test too. The name has no image extension: the format comes from the content.
const std::string& input_path() {
    static const std::string path = clr::fuzz::work_folder() + "/input";
    return path;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    clr::fuzz::write_file(input_path(), data, size);
    try {
        const auto image = clr::load_image(input_path());
        if (!image || image->width < 1 || image->height < 1 ||
            image->rgba.size() != static_cast<std::size_t>(image->width) * image->height * 4) {
            clr::fuzz::report_bug("load_image returned an image of inconsistent size", "");
        }
    } catch (const clr::ImageError& error) {
        // The expected way to refuse a file; the scene loader puts its reason in a message.
        const std::string reason = error.what();
        if (reason.empty()) clr::fuzz::report_bug("ImageError without a reason", "");
        if (!clr::fuzz::is_one_printable_line(reason)) clr::fuzz::report_bug("ImageError is not one printable line", reason);
    } catch (const std::exception& error) {
        clr::fuzz::report_bug(std::string("load_image threw ") + typeid(error).name() + " instead of clr::ImageError",
                              error.what());
    }
    return 0;
}
