## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{env} =} env_load (@var{map}, @var{fname})
## The radiance map of an environment light (private, for @code{scene_make}).
## @var{map} is the name of a lat-long HDR OpenEXR file, one of the names
## of @code{env_load ("names")} (the CC0 HDRIs of Debian's
## @code{blender-data}: without that package the built-in sky is used
## instead, with the warning @code{lafortune:noLightProbe}), @qcode{"sky"}
## (the built-in analytic sky: a blue sky brightening toward the horizon, a
## grey-brown ground and a sun disk), or an @var{H} x 2@var{H} x 3 array of
## radiance.  Row 1 of the map is straight up (+y), its centre column the
## direction -z (in front of the default cameras), its columns run toward
## +x.  @var{env} has the fields @code{map} (double), @code{name},
## @code{file} (empty for the sky and for arrays) and @code{clamped}
## (negative texels set to 0).  Texels a little below 0 are compression
## ringing (DWA-compressed files have them): those above -0.05 times the
## map's mean luminance are set to 0; a texel further below 0, a
## non-finite texel, a map that is not 2:1 or smaller than 4 x 8, and a
## file that does not exist or does not read give @code{lafortune:badMap}.
## @end deftypefn
function env = env_load (map, fname)
  names = {"city", "courtyard", "forest", "interior", "night", "studio", "sunrise", "sunset"};
  if (ischar (map) && strcmp (map, "names"))
    env = names;
    return;
  endif
  file = "";
  if (ischar (map))
    name = map;
    if (strcmp (map, "sky"))
      M = env_sky ();
    else
      if (any (strcmp (map, names)))
        file = probe_file (map);
        if (isempty (file))
          warning ("lafortune:noLightProbe",
                   "%s: the light probe '%s' comes with Debian's package blender-data, which is not installed (make deps installs it); using the built-in sky",
                   fname, map);
          M = env_sky ();
          name = "sky";
        endif
      else
        file = map;
        [~, name] = fileparts (map);
        if (! exist (file, "file"))
          error ("lafortune:badMap",
                 "%s: MAP '%s' is neither a file nor a light probe name (%s, sky)", fname,
                 map, strjoin (names, ", "));
        endif
      endif
      if (! isempty (file))
        try
          M = exrread (file);
        catch err
          error ("lafortune:badMap", "%s: cannot read the map '%s' as OpenEXR: %s", fname,
                 file, err.message);
        end_try_catch
        M = double (M(:,:,1:min (3, size (M, 3))));
        if (size (M, 3) == 1)
          M = repmat (M, [1 1 3]);
        endif
      endif
    endif
  elseif (isnumeric (map) && isreal (map))
    M = double (map);
    name = "map";
  else
    error ("lafortune:badMap",
           "%s: MAP must be a file name, a light probe name or an H x 2H x 3 radiance array, got %s",
           fname, class (map));
  endif
  if (ndims (M) != 3 || size (M, 3) != 3 || columns (M) != 2 * rows (M) || rows (M) < 4)
    error ("lafortune:badMap",
           "%s: the map must be a lat-long image twice as wide as high (at least 4 x 8) with 3 channels, got %s",
           fname, strjoin (arrayfun (@num2str, size (M), "UniformOutput", false), " x "));
  endif
  if (! all (isfinite (M(:))))
    error ("lafortune:badMap", "%s: the map '%s' has %d non-finite texels", fname, name,
           nnz (! isfinite (M(:))));
  endif
  Y = __lafortune_luminance__ (M);
  tol = 0.05 * max (mean (Y(:)), 0);
  neg = M < 0;
  if (any (M(:) < -tol) || ! any (M(:) > 0))
    error ("lafortune:badMap",
           "%s: the map '%s' has texels below 0 (down to %g; expected radiance >= 0, with ringing above -%g) or no light at all",
           fname, name, min (M(:)), tol);
  endif
  M(neg) = 0;
  env = struct ("map", M, "name", name, "file", file, "clamped", nnz (neg));
endfunction

## the file of a light probe of blender-data, or "" (versioned or not)
function f = probe_file (name)
  f = "";
  root = getenv ("LAFORTUNE_PROBES");
  if (isempty (root))
    dirs = [{"/usr/share/blender/datafiles/studiolights/world"}, ...
            cellfun(@(d) fullfile (d, "datafiles", "studiolights", "world"),
                    glob ("/usr/share/blender/[0-9]*"), "UniformOutput", false).'];
  else
    dirs = {root};
  endif
  for k = 1:numel (dirs)
    c = fullfile (dirs{k}, [name ".exr"]);
    if (exist (c, "file"))
      f = c;
      return;
    endif
  endfor
endfunction

## the built-in analytic sky, 128 x 256: sky radiance rising toward the
## horizon, a ground of albedo 0.2 under it, and a sun disk of radius 3
## degrees at elevation 35 degrees, azimuth 40 degrees right of -z
function M = env_sky ()
  H = 128;
  W = 2 * H;
  [c, r] = meshgrid ((0:W-1) + 0.5, (0:H-1) + 0.5);
  th = r / H * pi;
  ph = c / W * 2 * pi - pi;
  d = reshape (env_dirs (th(:), ph(:)), H, W, 3);
  el = pi / 2 - th;
  sky = [0.35 0.55 1.0];
  hor = [1.0 0.95 0.9];
  t = exp (-max (el, 0) / 0.35);
  M = zeros (H, W, 3);
  for k = 1:3
    M(:,:,k) = (1 - t) * sky(k) + t * hor(k);
  endfor
  g = el < 0;
  ground = [0.5 0.45 0.4] * 0.6;
  for k = 1:3
    ch = M(:,:,k);
    ch(g) = ground(k);
    M(:,:,k) = ch;
  endfor
  se = 35 * pi / 180;
  sa = 40 * pi / 180;
  s = [cos(se) * sin(sa), sin(se), -cos(se) * cos(sa)];
  cosd = d(:,:,1) * s(1) + d(:,:,2) * s(2) + d(:,:,3) * s(3);
  sun = cosd > cos (3 * pi / 180);
  for k = 1:3
    ch = M(:,:,k);
    ch(sun) = 200 * [1 0.95 0.85](k);
    M(:,:,k) = ch;
  endfor
endfunction
