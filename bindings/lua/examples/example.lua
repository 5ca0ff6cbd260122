-- The README's Lua example: reconstruct a sampled sphere and report the mesh.

-- Fibonacci points on the unit sphere as {{x, y, z}, ...}.
local function sample_points(n)
  local points = {}
  for i = 0, n - 1 do
    local y = 1 - 2 * (i + 0.5) / n
    local r, a = math.sqrt(1 - y * y), i * math.pi * (3 - math.sqrt(5))
    points[#points + 1] = { r * math.cos(a), y, r * math.sin(a) }
  end
  return points
end

local points = sample_points(1000)
-- --- README example begins ---
local moa = require("moa")
local reconstructor <close> = moa.Reconstructor()
reconstructor:set_points(points)                -- {{x, y, z}, ...} or {x1, y1, z1, x2, ...}
reconstructor:set_param("neighbors", 24)
reconstructor:set_progress(function(stage, fraction)
  if fraction == 1 then print(stage .. " done") end  -- return false to cancel
end)
local mesh = reconstructor:run()                -- raises error(message) on failure
print(#mesh.vertices .. " vertices, " .. #mesh.triangles .. " triangles")
-- mesh.triangles[i] = {a, b, c}: indices into mesh.vertices, from 1
-- --- README example ends ---
