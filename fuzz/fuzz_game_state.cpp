// libFuzzer target: cueball::game_state_from_json on arbitrary bytes (the
// state files of `cueball game shoot` and Python's GameState.from_json).
//
// Checked for every input: the reader returns or throws InvalidArgument
// (field and message non-empty); nothing else escapes, nothing crashes. For
// every accepted state: game_state_to_json -> game_state_from_json gives the
// same state exactly and the text is stable; legal_actions() answers; the
// learning environment's masks, observation and decoding of an action
// (rl/environment.hpp) answer without throwing.
#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>
#include <string_view>
#include <vector>

#include "cueball/core/errors.hpp"
#include "cueball/io/game_json.hpp"
#include "cueball/rl/environment.hpp"
#include "fuzz_common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    cueball::GameState s;
    try {
      s = cueball::game_state_from_json(text);
    } catch (const cueball::InvalidArgument& e) {
      cueball_fuzz::check_rejection(e, "game_state_from_json");
      return 0;
    }
    const std::string written = cueball::game_state_to_json(s, -1);
    cueball::GameState back;
    try {
      back = cueball::game_state_from_json(written);
    } catch (const cueball::InvalidArgument& e) {
      cueball_fuzz::fail("game_state_to_json wrote a state that game_state_from_json rejects", e.what() + ("\n" + written));
    }
    cueball_fuzz::check(back == s, "game_state_from_json(game_state_to_json(s)) != s", written);
    cueball_fuzz::check(cueball::game_state_to_json(back, -1) == written, "game_state_to_json is not stable", written);
    (void)cueball::legal_actions(s);
    cueball::EnvOptions options;
    options.game = s.config.kind;
    (void)cueball::action_masks(s);
    std::vector<float> observation(static_cast<std::size_t>(cueball::env_observation_size(s.config.kind)));
    cueball::write_observation(s, s.to_shoot, s.config.noise, observation.data());
    cueball::EnvAction a;
    a.ball = s.on.empty() ? 1 : s.on.front();
    a.strike = {0.3, -0.2, 0.1, 0.9, -0.9};
    (void)cueball::decode_action(options, s, a);
    options.form = cueball::ActionForm::target;
    (void)cueball::decode_action(options, s, a);
  } catch (const std::exception& e) {
    cueball_fuzz::unexpected(e, "game_state_from_json/game_state_to_json/legal_actions/rl");
  }
  return 0;
}
