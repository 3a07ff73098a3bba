// tessera synth for the 8-bit PNG formats (1 to 4 channels): see synth_request.hpp.
#include <cstdint>

#include "synth_run.hpp"

namespace cli::synth {

template int run_format<std::uint8_t, 1>(const arguments&, const request&);
template int run_format<std::uint8_t, 2>(const arguments&, const request&);
template int run_format<std::uint8_t, 3>(const arguments&, const request&);
template int run_format<std::uint8_t, 4>(const arguments&, const request&);

}  // namespace cli::synth
