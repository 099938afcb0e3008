## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {lafortune} {@var{scene} =} scene_make (@var{name})
## @deftypefnx {lafortune} {@var{scene} =} scene_make (@var{name}, @var{option}, @var{value}, @dots{})
## @deftypefnx {lafortune} {@var{names} =} scene_make ()
## Build one of the built-in scenes as a plain scene struct.
##
## Scenes (@var{name}):
##
## @table @asis
## @item "sphere"
## one unit sphere at the origin, seen from +z (the lit-sphere view).
## @item "spheres"
## four spheres of different sizes standing on the ground plane y = 0, seen
## from above the front; the light comes from the upper left, so every sphere
## casts a visible shadow on the plane.
## @item "torus"
## the built-in triangle mesh (@code{mesh_torus}, vertex normals), tilted
## 60 degrees toward the camera; option @code{"resolution"} ([nu nv], default
## [96 48], i.e. 9216 triangles; [224 224] gives 100352).
## @item "mesh"
## a triangle mesh read with @code{mesh_read} from option @code{"file"} (PLY or
## OBJ, e.g. the Stanford Happy Buddha @file{happy_vrip.ply} you download);
## without a file, the built-in torus.  The mesh is framed automatically,
## wherever it lies and whatever its size: turned y up (option
## @code{"up"}), centred at the origin and scaled to a largest side of 2
## (option @code{"normalize"}), and seen by a camera fitted to its bounding
## box: on the +z side of the box centre, looking at it, 5 half-sides (the
## box's largest) away; the orthographic @code{extent}, and for
## @code{"camera", "perspective"} the field of view, show the box's front
## with a 10% margin for the image's shape.  The point light is 10
## half-sides from the box centre.  The Happy Buddha thus fills 9/10 of the
## paper's 256 x 512 view.
## @end table
##
## Options (name/value pairs):
##
## @table @code
## @item "size"
## [@var{H} @var{W}] in pixels (a scalar means square), default [256 256], or
## @code{"paper"}: the paper's 256 x 512 image, taken as @var{W} = 256 wide and
## @var{H} = 512 high (portrait, the Happy Buddha's shape), i.e. [512 256].
## @item "spp"
## samples (primary rays) per pixel, default 16 (the paper: 128).
## @item "seed"
## integer seed of the pixel jitter, default 1.
## @item "jitter"
## true (default): each sample at a random place in its cell of the pixel
## (the @var{spp} samples of a pixel are stratified on a grid of cells);
## false: at the cell centres, deterministic, so that with @var{spp} = 1 it
## is the pixel centre and with @var{spp} = n^2 the regular grid of
## POV-Ray's anti-aliasing (@code{pov_render} option @qcode{"antialias"},
## n, which adds the centre ray): the mode for comparing renderers without
## sampling noise.
## @item "camera"
## @code{"orthographic"} (default) or @code{"perspective"} (same eye and
## target, the field of view that shows the orthographic extent at the target).
## @item "light"
## @code{"directional"} (default), @code{"point"} (placed at distance 10
## from the target along @code{"light_direction"}), @code{"environment"}
## (light from every direction, a lat-long radiance map: options
## @code{"map"}, @code{"rotation"}, @code{"intensity"},
## @code{"light_samples"}) or @code{"lights"} (several directional lights,
## the rows of @code{"light_direction"} with the rows of
## @code{"irradiance"}; @code{scene_lights} makes them from an
## environment).
## @item "light_direction"
## direction toward the light (normalised), default [-1 1 1] (sphere, torus,
## mesh) or [-1 1.6 0.9] (spheres); for @code{"lights"} a K x 3 array, one
## light per row.
## @item "irradiance"
## irradiance E on a surface facing the light, scalar or 1 x 3, default 1
## (for @code{"lights"} also K x 1 or K x 3, one row per light).
## For a point light it holds at the target; the struct stores the intensity
## E d^2.
## @item "map"
## the environment: a lat-long HDR OpenEXR file (twice as wide as high,
## row 1 straight up, the centre column in front of the camera, toward -z,
## the columns running toward +x), one of the names
## @code{"city"}, @code{"courtyard"} (default), @code{"forest"},
## @code{"interior"}, @code{"night"}, @code{"studio"}, @code{"sunrise"},
## @code{"sunset"} (the CC0 HDRIs of Debian's package @code{blender-data},
## which @code{make deps} installs; without it the built-in sky is used, with
## the warning @code{lafortune:noLightProbe}; the environment variable
## @env{LAFORTUNE_PROBES} names another folder of such files), @code{"sky"} (the built-in
## analytic sky: sky, ground and a sun disk) or an H x 2H x 3 array of
## radiance.  Slightly negative texels (compression ringing, above -0.05
## times the mean luminance) are set to 0; a missing or unreadable file,
## a map that is not 2:1, non-finite or negative texels give
## @code{lafortune:badMap}.  The map lights the scene; rays that hit
## nothing still show @code{"background"}.
## @item "rotation"
## turn of the environment about +y, in degrees (default 0).
## @item "intensity"
## factor on the map's radiance, scalar or 1 x 3, default 1.
## @item "light_samples"
## environment light: directions sampled per pixel sample, default 64
## (@code{rt_render} option @qcode{"light_samples"} overrides it).
## @item "background"
## 1 x 3 background radiance, default [0 0 0].
## @item "file"
## mesh file for the scene @code{"mesh"}.
## @item "resolution"
## [nu nv] of the built-in torus, default [96 48].
## @item "up"
## the mesh file's up axis: @code{"y"} (default) or @code{"z"}.  A z-up mesh
## is rotated by -90 degrees about x, (x, y, z) -> (x, z, -y), so that its
## z becomes the world's y and its -y side (the front in z-up tools such as
## Blender) faces the camera; the camera keeps y as its up vector, so the
## light directions mean the same for every mesh.
## @item "normalize"
## true (default): centre and scale the mesh as above; false: keep the
## file's coordinates (the camera and the point light are fitted to them
## all the same).
## @end table
##
## The struct (fields @code{name}, @code{width}, @code{height}, @code{spp},
## @code{seed}, @code{background}, @code{camera}, @code{light},
## @code{objects}, @code{mesh_info}) is the one documented in HACKING.md; the
## orthographic @code{extent} frames the objects with a margin for any
## aspect ratio.  For the scenes "mesh" and "torus", @code{mesh_info} is
## the @var{info} of @code{mesh_read} (counts: @code{polygons},
## @code{triangles}, @code{degenerate} triangles dropped, @code{faces},
## @code{vertices}, vertex @code{normals} and @code{split}) with the fields
## @code{up}, @code{rotation}, @code{center} and @code{scale}: the scene's
## vertices are (V * rotation.' - center) * scale for the file's V; for the
## other scenes it is empty.
## With no argument, the names of the scenes are returned.  An unknown scene
## gives the error @code{lafortune:unknownScene}, a bad option
## @code{lafortune:badOption}.
##
## @example
## @group
## scene = scene_make ("spheres", "size", [64 96], "spp", 4);
## model = struct ("rho_d", [0.2 0.1 0.05], "Cxy", [-1 -1 -1], ...
##                 "Cz", [1 1 1], "e", [40 40 40]);
## img = rt_render (scene, model);
## imshow (img / max (img(:)));
## scene = scene_make ("mesh", "file", "happy_vrip.ply", "size", "paper", "spp", 128);
## scene.mesh_info.degenerate               # triangles dropped
## scene = scene_make ("mesh", "file", "part.obj", "up", "z", "camera", "perspective");
## scene = scene_make ("spheres", "light", "environment", "map", "forest", ...
##                     "rotation", 120, "light_samples", 128);
## @end group
## @end example
## @seealso{rt_render, scene_lights, mesh_read, mesh_torus, scene_slice}
## @end deftypefn

function scene = scene_make (name, varargin)
  names = {"sphere", "spheres", "torus", "mesh"};
  if (nargin == 0)
    scene = names;
    return;
  endif
  if (! ischar (name) || ! any (strcmp (name, names)))
    if (ischar (name))
      what = sprintf ("'%s'", name);
    else
      what = sprintf ("a %s", class (name));
    endif
    error ("lafortune:unknownScene",
           "scene_make: unknown scene %s; valid scenes: %s", what, strjoin (names, ", "));
  endif
  opt = __lafortune_parse_opts__ (varargin, "scene_make",
                    struct ("size", [256 256], "spp", 16, "seed", 1,
                            "camera", "orthographic", "light", "directional",
                            "light_direction", [], "irradiance", 1,
                            "background", [0 0 0], "file", "", "resolution", [96 48],
                            "jitter", true, "up", "y", "normalize", true,
                            "map", "courtyard", "rotation", 0, "intensity", 1,
                            "light_samples", 64));
  [H, W] = check_size (opt.size);
  spp = opt.spp;
  if (! (isnumeric (spp) && isscalar (spp) && isreal (spp) && spp >= 1 && spp == fix (spp)))
    error ("lafortune:badOption", "scene_make: SPP must be a positive integer");
  endif
  seed = opt.seed;
  if (! (isnumeric (seed) && isscalar (seed) && isreal (seed) && isfinite (seed)
         && seed == fix (seed)))
    error ("lafortune:badOption", "scene_make: SEED must be an integer");
  endif
  if (! ischar (opt.camera) || ! any (strcmp (opt.camera, {"orthographic", "perspective"})))
    error ("lafortune:badOption",
           "scene_make: CAMERA must be \"orthographic\" or \"perspective\"");
  endif
  lights = {"directional", "point", "environment", "lights"};
  if (! ischar (opt.light) || ! any (strcmp (opt.light, lights)))
    error ("lafortune:badOption", "scene_make: LIGHT must be one of %s",
           strjoin (strcat ('"', lights, '"'), ", "));
  endif
  E = opt.irradiance;
  if (strcmp (opt.light, "lights"))
    E = check_lights (opt.light_direction, E);
  elseif (! (isnumeric (E) && isreal (E) && any (numel (E) == [1 3]) && all (isfinite (E))
             && all (E >= 0)))
    error ("lafortune:badOption",
           "scene_make: IRRADIANCE must be a scalar or 1 x 3 of finite values >= 0");
  endif
  bg = opt.background;
  if (! (isnumeric (bg) && isreal (bg) && numel (bg) == 3 && all (isfinite (bg))))
    error ("lafortune:badOption", "scene_make: BACKGROUND must be a finite 1 x 3 radiance");
  endif
  jit = opt.jitter;
  if (! (isscalar (jit) && (islogical (jit) || (isnumeric (jit) && any (jit == [0 1])))))
    error ("lafortune:badOption", "scene_make: JITTER must be true or false");
  endif
  if (! isempty (opt.file) && ! strcmp (name, "mesh"))
    error ("lafortune:badOption", "scene_make: option FILE is for the scene \"mesh\" only");
  endif
  if (! ischar (opt.up) || ! any (strcmpi (opt.up, {"y", "z"})))
    error ("lafortune:badOption", "scene_make: UP must be \"y\" or \"z\"");
  endif
  if (! ((islogical (opt.normalize) || isnumeric (opt.normalize)) && isscalar (opt.normalize)
         && any (opt.normalize == [0 1])))
    error ("lafortune:badOption", "scene_make: NORMALIZE must be true or false");
  endif
  if ((strcmpi (opt.up, "z") || ! opt.normalize) && isempty (opt.file))
    error ("lafortune:badOption",
           "scene_make: options UP and NORMALIZE are for a mesh read from a FILE");
  endif

  aspect = H / W;
  fov = [];                                  # [] for 2 * atand (extent / 2 / dist)
  ldist = 10;                                # point light: distance from the target
  mesh_info = [];
  switch (name)
    case "sphere"
      objects = make_obj ("sphere", "center", [0 0 0], "radius", 1);
      eye = [0 0 5];
      target = [0 0 0];
      extent = 2.3 * max (1, aspect);
      ldir = [-1 1 1];
    case "spheres"
      objects = [make_obj("plane", "point", [0 0 0], "normal", [0 1 0]), ...
                 make_obj("sphere", "center", [-1.6 0.7 -0.2], "radius", 0.7), ...
                 make_obj("sphere", "center", [0.3 1 -1], "radius", 1), ...
                 make_obj("sphere", "center", [1.7 0.5 0.5], "radius", 0.5), ...
                 make_obj("sphere", "center", [-0.1 0.35 1.2], "radius", 0.35)];
      target = [0 0.5 0];
      eye = [0 3.5 8];
      if (strcmp (opt.camera, "orthographic"))
        ## far back, so that the image plane stays above the ground plane
        eye = target + 4 * (eye - target);
      endif
      extent = max (3.6, 5.4 * aspect);
      ldir = [-1 1.6 0.9];
    case {"torus", "mesh"}
      if (strcmp (name, "mesh") && ! isempty (opt.file))
        if (! ischar (opt.file))
          error ("lafortune:badOption", "scene_make: FILE must be a file name");
        endif
        [V, F, N, mesh_info] = mesh_read (opt.file);
        [V, N, mesh_info] = mesh_place (V, N, mesh_info, opt.up, opt.normalize);
        lo = min (V, [], 1);
        hi = max (V, [], 1);
        [eye, target, extent, fov] = mesh_frame (lo, hi, aspect);
        ldist = 5 * max (hi - lo);           # 10 with "normalize"
      else
        [V, F, N] = mesh_torus (opt.resolution);
        a = 60 * pi / 180;                   # tilt the axis toward the camera
        Rx = [1 0 0; 0 cos(a) -sin(a); 0 sin(a) cos(a)];
        V = V * Rx.';
        N = N * Rx.';
        lo = min (V, [], 1);
        hi = max (V, [], 1);
        eye = [0 0 5];
        target = [0 0 0];
        extent = 1.1 * max (2 * max (abs ([lo(2) hi(2)])), 2 * max (abs ([lo(1) hi(1)])) * aspect);
        mesh_info = struct ("file", "", "format", "mesh_torus", "vertices", rows (V),
                            "faces", rows (F), "polygons", rows (F), "triangles", rows (F),
                            "degenerate", 0, "normals", "vertex", "split", 0, "filled", 0,
                            "up", "y", "rotation", [1 0 0; 0 1 0; 0 0 1],
                            "center", [0 0 0], "scale", 1);
      endif
      objects = make_obj ("mesh", "vertices", V, "faces", F, "normals", N);
      ldir = [-1 1 1];
  endswitch

  if (! isempty (opt.light_direction) && ! strcmp (opt.light, "lights"))
    ldir = opt.light_direction;
    if (! (isnumeric (ldir) && isreal (ldir) && numel (ldir) == 3 && all (isfinite (ldir))
           && norm (ldir) > 0))
      error ("lafortune:badOption",
             "scene_make: LIGHT_DIRECTION must be a finite non-zero 3-vector");
    endif
  endif
  ldir = double (ldir(:).') / norm (ldir);
  dist = norm (eye - target);
  camera = struct ("type", opt.camera, "eye", eye, "target", target, "up", [0 1 0],
                   "extent", extent, "fov", fov);
  if (isempty (fov))
    camera.fov = 2 * atand (extent / 2 / dist);
  endif
  if (strcmp (opt.light, "lights"))
    Ld = double (opt.light_direction);
    light = struct ("type", "lights", "direction", [], "position", [], "irradiance", E,
                    "directions", Ld ./ sqrt (sum (Ld .^ 2, 2)));
  elseif (strcmp (opt.light, "environment"))
    light = environment (opt, E);
  elseif (strcmp (opt.light, "directional"))
    E = double (E(:).');
    light = struct ("type", "directional", "direction", ldir, "position", [],
                    "irradiance", E);
  else
    E = double (E(:).');
    d = ldist;
    light = struct ("type", "point", "direction", [], "position", target + d * ldir,
                    "irradiance", E * d ^ 2);
  endif
  scene = struct ("name", name, "width", W, "height", H, "spp", double (spp),
                  "seed", double (seed), "jitter", logical (jit),
                  "background", double (bg(:).'),
                  "camera", camera, "light", light);
  scene.objects = objects;
  scene.mesh_info = mesh_info;
endfunction

## the directions and irradiances of a list of lights: K x 3 each
function E = check_lights (D, E)
  if (! (isnumeric (D) && isreal (D) && ndims (D) == 2 && columns (D) == 3 && rows (D) >= 1
         && all (isfinite (D(:))) && all (sum (D .^ 2, 2) > 0)))
    error ("lafortune:badOption",
           "scene_make: LIGHT \"lights\" needs LIGHT_DIRECTION, a K x 3 array of finite non-zero directions");
  endif
  K = rows (D);
  if (! (isnumeric (E) && isreal (E) && all (isfinite (E(:))) && all (E(:) >= 0)
         && (isscalar (E) || isequal (size (E), [1 3]) || isequal (size (E), [K 1])
             || isequal (size (E), [K 3]))))
    error ("lafortune:badOption",
           "scene_make: IRRADIANCE of %d lights must be a scalar, 1 x 3, %d x 1 or %d x 3, finite and >= 0",
           K, K, K);
  endif
  E = double (E) .* ones (K, 3);
endfunction

## an environment light: the map (env_load), its turn, intensity and samples
function light = environment (opt, E)
  a = opt.rotation;
  if (! (isnumeric (a) && isreal (a) && isscalar (a) && isfinite (a)))
    error ("lafortune:badOption", "scene_make: ROTATION must be a finite angle in degrees");
  endif
  k = opt.intensity;
  if (! (isnumeric (k) && isreal (k) && any (numel (k) == [1 3]) && all (isfinite (k))
         && all (k >= 0)))
    error ("lafortune:badOption",
           "scene_make: INTENSITY must be a scalar or 1 x 3 of finite values >= 0");
  endif
  ns = opt.light_samples;
  if (! (isnumeric (ns) && isscalar (ns) && isreal (ns) && ns >= 1 && ns == fix (ns)))
    error ("lafortune:badOption", "scene_make: LIGHT_SAMPLES must be a positive integer");
  endif
  env = env_load (opt.map, "scene_make");
  light = struct ("type", "environment", "direction", [], "position", [],
                  "irradiance", double (k(:).') .* double (E(:).'), "map", env.map,
                  "name", env.name, "file", env.file, "rotation", double (a),
                  "samples", double (ns), "clamped", env.clamped);
endfunction

function [H, W] = check_size (sz)
  if (ischar (sz))
    if (! strcmpi (sz, "paper"))
      error ("lafortune:badOption",
             "scene_make: SIZE must be [H W] or \"paper\", got \"%s\"", sz);
    endif
    H = 512;
    W = 256;
    return;
  endif
  if (! (isnumeric (sz) && isreal (sz) && any (numel (sz) == [1 2]) && all (sz >= 1)
         && all (sz == fix (sz)) && all (isfinite (sz))))
    error ("lafortune:badOption",
           "scene_make: SIZE must be [H W] (positive integers) or \"paper\"");
  endif
  if (isscalar (sz))
    sz = [sz sz];
  endif
  H = double (sz(1));
  W = double (sz(2));
endfunction

function o = make_obj (type, varargin)
  o = struct ("type", type, "center", [], "radius", [], "point", [], "normal", [],
              "vertices", [], "faces", [], "normals", []);
  for k = 1:2:numel (varargin)
    o.(varargin{k}) = varargin{k+1};
  endfor
endfunction

%!test
%! s = scene_make ("sphere");
%! assert (s.name, "sphere");
%! assert ([s.height s.width s.spp s.seed], [256 256 16 1]);
%! assert (s.background, [0 0 0]);
%! assert (s.camera.type, "orthographic");
%! assert (s.light.type, "directional");
%! assert (norm (s.light.direction), 1, 1e-15);
%! assert (numel (s.objects), 1);
%! assert (s.objects.type, "sphere");
%! assert (s.objects.radius, 1);
%! ## the whole sphere is in view
%! assert (s.camera.extent > 2);

%!test
%! s = scene_make ("spheres", "size", "paper", "spp", 128, "seed", 7);
%! assert ([s.height s.width s.spp s.seed], [512 256 128 7]);
%! assert ({s.objects.type}, {"plane", "sphere", "sphere", "sphere", "sphere"});
%! ## spheres rest on the plane y = 0
%! c = vertcat (s.objects(2:end).center);
%! assert (c(:,2), [s.objects(2:end).radius]', 1e-15);
%! ## the whole row of spheres fits the (narrow) width
%! assert (s.camera.extent * s.width / s.height >= 2 * 2.2);
%! ## every orthographic camera ray starts above the ground and meets it
%! f = s.camera.target - s.camera.eye; f /= norm (f);
%! up = cross (cross (f, s.camera.up), f); up /= norm (up);
%! assert (s.camera.eye(2) - s.camera.extent / 2 * abs (up(2)) > 0);
%! assert (f(2) < 0);

%!test
%! s = scene_make ("torus", "resolution", [16 8], "size", [20 30]);
%! assert (s.objects.type, "mesh");
%! assert (size (s.objects.faces), [256 3]);
%! assert (size (s.objects.normals), [128 3]);
%! m = scene_make ("mesh", "resolution", [16 8]);
%! assert (m.objects.vertices, s.objects.vertices);
%! ## the mesh fits the view
%! V = s.objects.vertices;
%! assert (max (abs (V(:,2))) < s.camera.extent / 2);
%! assert (max (abs (V(:,1))) < s.camera.extent / 2 * 30 / 20);

%!test
%! ## a mesh from a file is centred and scaled to a largest extent of 2
%! f = [tempname() ".obj"];
%! fid = fopen (f, "w");
%! fprintf (fid, "v 10 10 10\nv 14 10 10\nv 10 11 10\nv 10 10 12\nf 1 2 3\nf 1 2 4\n");
%! fclose (fid);
%! s = scene_make ("mesh", "file", f);
%! V = s.objects.vertices;
%! assert (max (V) - min (V), [2 0.5 1], 1e-12);
%! assert ((max (V) + min (V)) / 2, [0 0 0], 1e-12);
%! assert (isempty (s.objects.normals));
%! assert ([s.mesh_info.polygons s.mesh_info.degenerate s.mesh_info.scale], [2 0 0.5]);
%! assert (s.mesh_info.center, [12 10.5 11]);
%! ## the camera is fitted to the box: the same frame with "normalize", false
%! t = scene_make ("mesh", "file", f, "normalize", false, "camera", "perspective");
%! assert (t.objects.vertices(1,:), [10 10 10]);
%! assert (t.camera.target, [12 10.5 11]);
%! assert (t.camera.eye, [12 10.5 21]);
%! assert (t.camera.extent, 2 * s.camera.extent);
%! assert (t.camera.fov, s.camera.fov, 1e-12);
%! delete (f);
%! assert (isempty (scene_make ("sphere").mesh_info));
%! assert (scene_make ("torus", "resolution", [8 4]).mesh_info.faces, 64);

%!test
%! s = scene_make ("sphere", "camera", "perspective", "light", "point", ...
%!                 "light_direction", [0 0 2], "irradiance", [1 2 3]);
%! assert (s.camera.type, "perspective");
%! assert (s.camera.fov > 0 && s.camera.fov < 90);
%! assert (s.light.position, [0 0 10]);
%! assert (s.light.irradiance, [100 200 300]);
%! s = scene_make ("sphere", "size", 32, "light_direction", [0 3 4]);
%! assert ([s.height s.width], [32 32]);
%! assert (s.light.direction, [0 0.6 0.8], 1e-15);
%! assert (scene_make (), {"sphere", "spheres", "torus", "mesh"});

%!test
%! ## an environment light on every scene: the built-in sky, a map array
%! for n = scene_make ()
%!   s = scene_make (n{1}, "light", "environment", "map", "sky", "resolution", [8 4],
%!                   "rotation", 30, "intensity", [1 2 3], "light_samples", 5);
%!   assert (s.light.type, "environment");
%!   assert (size (s.light.map), [128 256 3]);
%!   assert ([s.light.rotation s.light.samples], [30 5]);
%!   assert (s.light.irradiance, [1 2 3]);
%! endfor
%! M = ones (4, 8, 3);
%! M(1) = -0.01;                                 # ringing: set to 0, counted
%! s = scene_make ("sphere", "light", "environment", "map", M);
%! assert ([s.light.map(1) s.light.clamped], [0 1]);
%! assert (s.light.name, "map");
%! ## a list of directional lights
%! s = scene_make ("sphere", "light", "lights", "light_direction", [0 0 2; 1 0 0],
%!                 "irradiance", [1; 2]);
%! assert (s.light.directions, [0 0 1; 1 0 0]);
%! assert (s.light.irradiance, [1 1 1; 2 2 2]);

%!test
%! ## a light probe of blender-data, read from its OpenEXR file (make deps
%! ## installs the package; without it the built-in sky, with a warning)
%! f = "/usr/share/blender/datafiles/studiolights/world/forest.exr";
%! if (! exist (f, "file"))
%!   warning ("off", "lafortune:noLightProbe", "local");
%!   s = scene_make ("sphere", "light", "environment", "map", "forest");
%!   assert (s.light.name, "sky");
%!   printf ("skipped: blender-data is not installed (the built-in sky stands in)\n");
%! else
%!   s = scene_make ("sphere", "light", "environment", "map", "forest");
%!   assert (s.light.name, "forest");
%!   assert (s.light.file, f);
%!   assert (size (s.light.map), [512 1024 3]);
%!   assert (all (s.light.map(:) >= 0));
%!   t = scene_make ("sphere", "light", "environment", "map", f);
%!   assert (isequal (t.light.map, s.light.map));
%! endif

%!test
%! ## without blender-data's light probes: the built-in sky, and the toolbox
%! ## says so (a folder without them stands for the missing package)
%! d = tempname (); mkdir (d);
%! old = getenv ("LAFORTUNE_PROBES");
%! unwind_protect
%!   setenv ("LAFORTUNE_PROBES", d);
%!   warning ("error", "lafortune:noLightProbe", "local");
%!   try
%!     scene_make ("sphere", "light", "environment", "map", "city");
%!     error ("no warning");
%!   catch err
%!     assert (err.identifier, "lafortune:noLightProbe");
%!     assert (! isempty (strfind (err.message, "blender-data")));
%!   end_try_catch
%!   warning ("off", "lafortune:noLightProbe", "local");
%!   s = scene_make ("sphere", "light", "environment", "map", "city");
%!   assert (s.light.name, "sky");
%!   assert (isequal (s.light.map, scene_make ("sphere", "light", "environment", "map", "sky").light.map));
%!   ## the folder's own files are found by name
%!   exrwrite (fullfile (d, "city.exr"), ones (4, 8, 3));
%!   s = scene_make ("sphere", "light", "environment", "map", "city");
%!   assert ([s.light.name, size(s.light.map)], ["city", 4 8 3]);
%! unwind_protect_cleanup
%!   setenv ("LAFORTUNE_PROBES", old);
%!   confirm_recursive_rmdir (false, "local");
%!   rmdir (d, "s");
%! end_unwind_protect

%!test
%! ## a map that is not an OpenEXR file, and one in a file that is corrupt
%! d = tempname (); mkdir (d);
%! unwind_protect
%!   f = fullfile (d, "bad.exr");
%!   fid = fopen (f, "w"); fwrite (fid, uint8 ([118 47 49 1 2 0 0 0 0 0 7])); fclose (fid);
%!   try
%!     scene_make ("sphere", "light", "environment", "map", f);
%!     error ("no error");
%!   catch err
%!     assert (err.identifier, "lafortune:badMap");
%!   end_try_catch
%!   g = fullfile (d, "square.exr");
%!   exrwrite (g, ones (8, 8, 3));
%!   try
%!     scene_make ("sphere", "light", "environment", "map", g);
%!     error ("no error");
%!   catch err
%!     assert (err.identifier, "lafortune:badMap");
%!     assert (! isempty (strfind (err.message, "twice as wide")));
%!   end_try_catch
%! unwind_protect_cleanup
%!   confirm_recursive_rmdir (false, "local");
%!   rmdir (d, "s");
%! end_unwind_protect

%!error id=lafortune:badMap scene_make ("sphere", "light", "environment", "map", "/nonexistent/x.exr")
%!error id=lafortune:badMap scene_make ("sphere", "light", "environment", "map", "nowhere")
%!error <twice as wide> scene_make ("sphere", "light", "environment", "map", ones (8, 8, 3))
%!error <non-finite> scene_make ("sphere", "light", "environment", "map", [ones(4, 7, 3), NaN(4, 1, 3)])
%!error <below 0> scene_make ("sphere", "light", "environment", "map", -ones (4, 8, 3))
%!error <no light> scene_make ("sphere", "light", "environment", "map", zeros (4, 8, 3))
%!error id=lafortune:badMap scene_make ("sphere", "light", "environment", "map", {1})
%!error id=lafortune:badOption scene_make ("sphere", "light", "environment", "map", "sky", "rotation", NaN)
%!error id=lafortune:badOption scene_make ("sphere", "light", "environment", "map", "sky", "rotation", [1 2])
%!error id=lafortune:badOption scene_make ("sphere", "light", "environment", "map", "sky", "intensity", -1)
%!error id=lafortune:badOption scene_make ("sphere", "light", "environment", "map", "sky", "light_samples", 0)
%!error id=lafortune:badOption scene_make ("sphere", "light", "lights", "light_direction", [0 0 0])
%!error id=lafortune:badOption scene_make ("sphere", "light", "lights", "light_direction", [0 0 1; 0 1 0], "irradiance", [1 2 3 4])
%!error id=lafortune:unknownScene scene_make ("teapot")
%!error <valid scenes: sphere, spheres, torus, mesh> scene_make ("teapot")
%!error id=lafortune:unknownScene scene_make (3)
%!error id=lafortune:badOption scene_make ("sphere", "size", [0 3])
%!error id=lafortune:badOption scene_make ("sphere", "size", "huge")
%!error id=lafortune:badOption scene_make ("sphere", "spp", 1.5)
%!error id=lafortune:badOption scene_make ("sphere", "camera", "fisheye")
%!error id=lafortune:badOption scene_make ("sphere", "light", "area")
%!error id=lafortune:badOption scene_make ("sphere", "light_direction", [0 0 0])
%!error id=lafortune:badOption scene_make ("sphere", "irradiance", -1)
%!error id=lafortune:badOption scene_make ("sphere", "file", "x.ply")
%!error id=lafortune:badOption scene_make ("sphere", "colour", 1)
%!error id=lafortune:badOption scene_make ("sphere", "jitter", 2)
%!test
%! assert (scene_make ("sphere").jitter, true);
%! assert (scene_make ("sphere", "jitter", false).jitter, false);
%!error id=lafortune:meshReadNotFound scene_make ("mesh", "file", "/nonexistent/x.ply")
%!error id=lafortune:badOption scene_make ("mesh", "file", "x.ply", "up", "-z")
%!error id=lafortune:badOption scene_make ("torus", "normalize", false)

%!demo
%! ## the four built-in scenes, small and quick
%! m = struct ("rho_d", [0.25 0.1 0.05], "Cxy", [-1 -1 -1], "Cz", [0.95 0.95 0.95], ...
%!             "e", [30 30 30]);
%! n = scene_make ();
%! for k = 1:3
%!   img = rt_render (scene_make (n{k}, "size", [96 96], "spp", 2), m, "progress", false);
%!   subplot (1, 3, k); imshow (min (img / prctile (img(:), 99.5), 1)); title (n{k});
%! endfor
