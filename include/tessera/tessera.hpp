// tessera/tessera.hpp: umbrella header. Includes the core vocabulary and every algorithm; optional
// parts (io/, adapters/) are included separately since they need extra libraries.
// Docs and examples include the specific header instead, which compiles faster.
#pragma once

#include "version.hpp"
#include "core/config.hpp"
#include "core/executor.hpp"
#include "core/explain.hpp"
#include "core/format.hpp"
#include "core/image.hpp"
#include "core/image_buffer.hpp"
#include "core/image_checks.hpp"
#include "core/image_view.hpp"
#include "core/mesh.hpp"
#include "core/mesh_topology.hpp"
#include "core/mesh_view.hpp"
#include "core/progress.hpp"
#include "core/random.hpp"
#include "core/status.hpp"
#include "core/tile_coloring.hpp"
#include "core/tri_mesh.hpp"
#include "core/vec.hpp"
