// The worker process of the studio: it opens one model at a time as a
// Simulation and answers the server's requests (api/simulation.h does the
// work; this file only translates requests and answers). Models run here,
// never in the server, so a model that crashes, loops or exhausts memory
// takes only its worker down.
//
// Requests (worker_protocol.h messages, "op" naming each):
//   open    {model, inputs: [{path, kind, slot}], defines: [..], include_dirs: [..],
//            cache_dir, compiler, language}  -> status, animation, views
//   step    {count}      derives up to `count` steps, not past the derivation length -> status
//   run     {to}         derives to step `to` (-1: the derivation length) -> status
//   rewind  {}           back to the axiom (step 0) -> status
//   scene   {view, instances_above} -> the picture (payload): binary glTF ("glb_size"
//            bytes), then a big scene's instances (scene_instances.h); its camera ("view")
//   string  {offset, limit, search}, counts {}, module {index}
//   export  {format, view, width, height} -> the file's bytes (payload)
// Every answer has "ok"; a failed one has "error": {message, file, line, column}.
#pragma once

namespace sylva::studio {

// Serves requests read from `requests` until it is closed; answers go to
// `answers`. Returns the process's exit status.
int run_worker(int requests, int answers);

}  // namespace sylva::studio
