-- The Lua face of libmoa: what require("moa") returns. This chunk is compiled into moa.so and
-- run once by luaopen_moa with the SWIG-generated module (the raw layer) as its argument.
local native = ...

local NativeContext = native.NativeContext

local moa = { version = NativeContext.version() }

-- Raises libmoa's message for a failed status, blaming the caller of the public function.
local function check(ctx, status)
  if status ~= 0 then error(ctx:last_error(), 3) end
end

-- Flattens {{x, y, z}, ...} or {{x = .., y = .., z = ..}, ...}; a flat table passes through.
local function flatten(points)
  if type(points) ~= "table" then
    error("points must be a table, got " .. type(points), 3)
  end
  if type(points[1]) ~= "table" then return points end
  local flat = {}
  for i, p in ipairs(points) do
    local x, y, z
    if type(p) == "table" then
      x, y, z = p[1] or p.x, p[2] or p.y, p[3] or p.z
    end
    if type(x) ~= "number" or type(y) ~= "number" or type(z) ~= "number" then
      error(("point %d is not {x, y, z}"):format(i), 3)
    end
    flat[3 * i - 2], flat[3 * i - 1], flat[3 * i] = x, y, z
  end
  return flat
end

local Reconstructor = {}
Reconstructor.__index = Reconstructor

-- Frees the native context now instead of at garbage collection; also the <close> handler.
function Reconstructor:close()
  self._ctx:close()
end
Reconstructor.__close = Reconstructor.close

local function context(self)
  local ctx = self._ctx
  if not ctx:is_open() then error("the reconstructor is closed", 3) end
  return ctx
end

-- points: flat {x1, y1, z1, x2, ...} or {{x, y, z}, ...}. Copied; discards the last mesh.
function Reconstructor:set_points(points)
  local ctx = context(self)
  check(ctx, ctx:set_points(flatten(points)))
end

-- Parameters keep their values across runs and point sets.
function Reconstructor:set_param(name, value)
  local ctx = context(self)
  check(ctx, ctx:set_param(name, value))
end

function Reconstructor:get_param(name)
  local ctx = context(self)
  local status, value = ctx:get_param(name)
  check(ctx, status)
  return value
end

-- params: {name = value, ...}
function Reconstructor:set_params(params)
  for name, value in pairs(params) do self:set_param(name, value) end
end

-- fn(stage, fraction) is called during run with the stage's name ("points", "neighbors",
-- "mesh", "loops", "finish") and the part of it done; returning false cancels the run.
-- nil removes it.
function Reconstructor:set_progress(fn)
  self._progress = fn
end

-- Returns {vertices = {{x, y, z}, ...}, triangles = {{a, b, c}, ...}} where a, b, c index
-- vertices (from 1); the vertices are the points in their order.
function Reconstructor:run()
  local ctx = context(self)
  check(ctx, native.run(ctx, self._progress))
  local vertices, triangles = native.mesh(ctx)
  return { vertices = vertices, triangles = triangles }
end

function moa.Reconstructor()
  local ctx = NativeContext()
  local status = ctx:open()
  if status ~= 0 then error(ctx:last_error(), 2) end
  return setmetatable({ _ctx = ctx }, Reconstructor)
end

-- One call: points and optional parameters in, mesh out.
function moa.reconstruct(points, params)
  local r <close> = moa.Reconstructor()
  r:set_points(points)
  if params then r:set_params(params) end
  return r:run()
end

-- The parameter table: {{name =, description =, default =, min =, max =, integral =}, ...}
function moa.params()
  local list = {}
  for i = 0, NativeContext.param_count() - 1 do
    local p = NativeContext.param_info(i)
    list[#list + 1] = {
      name = p.name, description = p.description, default = p.default_value,
      min = p.min_value, max = p.max_value, integral = p.integral,
    }
  end
  return list
end

return moa
