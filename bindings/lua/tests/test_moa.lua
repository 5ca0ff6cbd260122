-- Tests of the Lua binding, run by CTest with lua5.4. Exits non-zero when a test fails.
local moa = require("moa")

local SPHERE_POINTS = 500

-- Fibonacci points on a sphere of radius 2 as {{x, y, z}, ...}: an evenly sampled closed surface.
local function sphere(n)
  local points, golden = {}, math.pi * (3 - math.sqrt(5))
  for i = 0, n - 1 do
    local y = 1 - 2 * (i + 0.5) / n
    local r = math.sqrt(1 - y * y)
    points[i + 1] = { 2 * r * math.cos(golden * i), 2 * y, 2 * r * math.sin(golden * i) }
  end
  return points
end

local function flat(points)
  local xyz = {}
  for _, p in ipairs(points) do
    xyz[#xyz + 1], xyz[#xyz + 2], xyz[#xyz + 3] = p[1], p[2], p[3]
  end
  return xyz
end

-- Runs fn and returns the message it raised.
local function raises(fn, ...)
  local ok, message = pcall(fn, ...)
  assert(not ok, "expected an error")
  return tostring(message)
end

local function has(message, fragment)
  assert(message:find(fragment, 1, true), ("%q lacks %q"):format(message, fragment))
end

local function check_mesh(mesh, n)
  assert(#mesh.vertices == n, "vertex count " .. #mesh.vertices)
  assert(#mesh.triangles > n, "triangle count " .. #mesh.triangles)
  for _, t in ipairs(mesh.triangles) do
    assert(#t == 3, "three corners")
    for k = 1, 3 do
      assert(math.type(t[k]) == "integer" and t[k] >= 1 and t[k] <= n, "index range")
    end
    assert(t[1] ~= t[2] and t[2] ~= t[3] and t[3] ~= t[1], "distinct corners")
  end
end

local tests = {}

function tests.sphere_nested_and_flat()
  local points = sphere(SPHERE_POINTS)
  local r <close> = moa.Reconstructor()
  r:set_points(points)
  local mesh = r:run()
  check_mesh(mesh, SPHERE_POINTS)
  for i, p in ipairs(points) do
    for k = 1, 3 do assert(mesh.vertices[i][k] == p[k], "vertices are the points") end
  end
  r:set_points(flat(points))
  local again = r:run()
  assert(#again.triangles == #mesh.triangles, "flat and nested give the same mesh")
  for i, t in ipairs(mesh.triangles) do
    for k = 1, 3 do assert(again.triangles[i][k] == t[k], "same triangles") end
  end
end

function tests.one_call_with_params()
  local named = {}
  for i, p in ipairs(sphere(SPHERE_POINTS)) do named[i] = { x = p[1], y = p[2], z = p[3] } end
  check_mesh(moa.reconstruct(named, { neighbors = 24, threads = 1 }), SPHERE_POINTS)
end

function tests.errors()
  local r <close> = moa.Reconstructor()
  r:set_param("neighbors", 24)
  assert(r:get_param("neighbors") == 24, "a parameter keeps its value")
  has(raises(r.set_param, r, "no_such_param", 1), "no_such_param")
  has(raises(r.set_param, r, "neighbors", 1e9), "neighbors")
  has(raises(r.set_points, r, { 1, 2, 3, 4 }), "4 values")
  has(raises(r.set_points, r, { 1, 2, "x" }), "not a number")
  has(raises(r.set_points, r, { { 1, 2 } }), "point 1")
  has(raises(r.run, r), "no points")
  r:close()
  has(raises(r.set_param, r, "threads", 1), "closed")
  local names = {}
  for _, p in ipairs(moa.params()) do names[p.name] = true end
  assert(names.neighbors and names.threads, "parameter table")
end

function tests.cancel_then_run_again()
  local r <close> = moa.Reconstructor()
  r:set_points(sphere(SPHERE_POINTS))
  local stages = {}
  r:set_progress(function(stage, fraction)
    assert(fraction >= 0 and fraction <= 1, "fraction")
    stages[#stages + 1] = stage
    return stage ~= "mesh"
  end)
  has(raises(r.run, r), "cancel")
  assert(stages[#stages] == "mesh", "stopped at mesh")
  stages = {}
  r:set_progress(function(stage) stages[#stages + 1] = stage end)
  check_mesh(r:run(), SPHERE_POINTS)
  assert(stages[1] == "points" and stages[#stages] == "finish", "every stage")
  r:set_progress(function() error("from the callback") end)
  has(raises(r.run, r), "from the callback")
end

local names, failed = {}, 0
for name in pairs(tests) do names[#names + 1] = name end
table.sort(names)
for _, name in ipairs(names) do
  local ok, message = pcall(tests[name])
  print((ok and "ok   " or "FAIL ") .. name .. (ok and "" or ": " .. tostring(message)))
  if not ok then failed = failed + 1 end
end
print(("libmoa %s: %d failed"):format(moa.version, failed))
os.exit(failed == 0 and 0 or 1)
