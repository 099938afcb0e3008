## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {[@dots{}] =} pov_sdl (@var{what}, @dots{})
## pov_write_scene's SDL text (private): POV-Ray 3.7 scene language for
## tables and scene parts already computed, no numerics of their own.
## @var{what} is one of @code{"table"} (one term's nested pigment_maps),
## @code{"gamma"} (a perspective camera's pigment over gamma levels),
## @code{"header"}, @code{"frames"} (the head of a scene of K lights, one
## frame each, which includes BASE_Lkkkk.inc in frame k), @code{"camera"},
## @code{"light"}, @code{"texture"},
## @code{"objects"} (returns the text and the faces left out) and
## @code{"vec"} (a 3-vector as <x, y, z>).
## @end deftypefn
function varargout = pov_sdl (what, varargin)
  switch (what)
    case "gamma"
      [varargout{1:max (nargout, 1)}] = gamma_sdl (varargin{:});
    case "vec"
      [varargout{1:max (nargout, 1)}] = vec (varargin{:});
    case "table"
      [varargout{1:max (nargout, 1)}] = table_sdl (varargin{:});
    case "header"
      [varargout{1:max (nargout, 1)}] = header_sdl (varargin{:});
    case "frames"
      [varargout{1:max (nargout, 1)}] = frames_sdl (varargin{:});
    case "camera"
      [varargout{1:max (nargout, 1)}] = camera_sdl (varargin{:});
    case "light"
      [varargout{1:max (nargout, 1)}] = light_sdl (varargin{:});
    case "texture"
      [varargout{1:max (nargout, 1)}] = texture_sdl (varargin{:});
    case "objects"
      [varargout{1:max (nargout, 1)}] = objects_sdl (varargin{:});
    otherwise
      error ("pov_sdl: unknown part '%s'", what);
  endswitch
endfunction

## the pigment ID of a term under a perspective camera: a function pattern
## of the position, gamma/pi = angle (L, eye - P)/pi, indexes its levels
function s = gamma_sdl (id, name, gl, eye, L)
  e = eye;
  fn = sprintf (["acos(min(1,max(-1,(%.12g*(%.12g-x)+%.12g*(%.12g-y)+%.12g*(%.12g-z))" ...
                 "/sqrt((%.12g-x)*(%.12g-x)+(%.12g-y)*(%.12g-y)+(%.12g-z)*(%.12g-z)+1e-30))))/pi"],
                L(1), e(1), L(2), e(2), L(3), e(3), e(1), e(1), e(2), e(2), e(3), e(3));
  s = sprintf ("// %s: %d levels of gamma = angle (L, V) from %.6g to %.6g rad\n#declare %s = pigment { function { %s } pigment_map {\n",
               name, numel (gl), gl(1), gl(end), id, fn);
  for g = 1:numel (gl)
    s = [s, sprintf("[%.9g %s_%d]\n", gl(g) / pi, id, g)];
  endfor
  s = [s, "} }\n"];
endfunction

function s = vec (v)
  v(v == 0) = 0;                 # no "-0"
  s = sprintf ("<%.12g, %.12g, %.12g>", v);
endfunction

## one table: slope toward L outside (ti, descending so that the slope value
## 1 - ti/pi ascends), INNER inside (slope toward H or V, or aoi)
function s = table_sdl (id, name, T, ti, to, io, Ki, L, inner)
  parts = cell (1, numel (io) + 2);
  parts{1} = sprintf (["// %s: %d outer entries (angle to the light), inner entries per outer: %d to %d\n" ...
                       "#declare %s = pigment { slope { %s } pigment_map {\n"],
                      name, numel (io), min (sum (Ki, 1)), max (sum (Ki, 1)), id, vec (L));
  for k = numel (io):-1:1
    jo = flipud (find (Ki(:,k)));
    v = [1 - to(jo)'/pi; reshape(T(io(k),jo,:), numel (jo), 3)'];
    parts{numel (io) - k + 2} = [sprintf("[%.9g %s pigment_map {\n", 1 - ti(io(k))/pi, inner), ...
                                 sprintf("[%.9g rgb <%.7g,%.7g,%.7g>]\n", v), "}]\n"];
  endfor
  parts{end} = "} }\n";
  s = [parts{:}];
endfunction

function s = header_sdl (scene, material, opt, tabs, rng_i, rng_o, peak, C)
  nm = __lafortune_name_of__ (material);
  sname = __lafortune_name_of__ (scene);
  s = sprintf (["// POV-Ray 3.7 scene written by pov_write_scene (lafortune package)\n" ...
                "// scene '%s', material '%s', %d x %d pixels\n" ...
                "// render: povray +I<this> +O<out>.exr +FE +W%d +H%d -A File_Gamma=1.0\n" ...
                "// tables of f(wi,wo)*E over ti = angle(N,L) in [%.6g, %.6g], %s in [%.6g, %.6g] rad\n" ...
                "// (slope value = 1 - angle/pi); knots %s, entries <= %d, table_tol %g, lobe_tol %g,\n" ...
                "// largest radiance %.6g\n"],
               sname, nm, scene.width, scene.height, scene.width, scene.height,
               rng_i, C.label, rng_o, opt.knots, opt.entries, opt.table_tol, opt.lobe_tol, peak);
  for q = 1:numel (tabs)
    if (tabs(q).kept)
      st = "kept";
    else
      st = "left out";
    endif
    s = [s, sprintf("// %s: largest radiance %.3g of the whole, %s\n", tabs(q).name,
                    tabs(q).contribution, st)];
  endfor
  bg = [0 0 0];
  if (isfield (scene, "background") && numel (scene.background) >= 1)
    bg = double (scene.background(:)') .* [1 1 1];
  endif
  s = [s, sprintf("#version 3.7;\nglobal_settings { assumed_gamma 1.0 ambient_light rgb 0 }\n"), ...
       sprintf("background { rgb %s }\n", vec (bg))];
endfunction

## the head of a scene of K directional lights, one per frame: frame k
## includes BASE_Lkkkk.inc (light k and its tables); the background is in
## frame 1 only, so that the frames add up to the image
function s = frames_sdl (scene, material, K, base)
  bg = double (scene.background(:)') .* [1 1 1];
  s = sprintf (["// POV-Ray 3.7 scene written by pov_write_scene (lafortune package)\n" ...
                "// scene '%s', material '%s', %d x %d pixels, %d directional lights, one per frame:\n" ...
                "// frame k includes %s_Lkkkk.inc (light k and its tables); the image is the sum of the frames\n" ...
                "// render: povray +I<this> +O<out>.exr +FE +W%d +H%d -A File_Gamma=1.0 +KFI1 +KFF%d\n" ...
                "#version 3.7;\nglobal_settings { assumed_gamma 1.0 ambient_light rgb 0 }\n" ...
                "#if (frame_number < 1 | frame_number > %d)\n" ...
                "#error \"render this scene as an animation, +KFI1 +KFF%d: frame k is light k\"\n#end\n" ...
                "#if (frame_number = 1) background { rgb %s } #else background { rgb 0 } #end\n" ...
                "#include concat (\"%s_L\", str (frame_number, -4, 0), \".inc\")\n"],
               __lafortune_name_of__ (scene), __lafortune_name_of__ (material), scene.width, scene.height, K, base,
               scene.width, scene.height, K, K, K, vec (bg), base);
endfunction

function s = camera_sdl (cam, scene)
  s = sprintf (["// right-handed, y-up world; explicit vectors, so POV-Ray does not mirror\n" ...
                "camera { %s location %s direction %s right %s up %s }\n"],
               cam.type, vec (cam.eye), vec (cam.f), vec (cam.r * cam.w), vec (cam.u * cam.h));
endfunction

function s = light_sdl (scene, L, cam)
  ## far enough that every object is in front of it
  ob = scene.objects;
  ext = norm (cam.eye - double (scene.camera.target(:)')) + cam.w + cam.h;
  for k = 1:numel (ob)
    switch (ob(k).type)
      case "sphere"
        ext = max (ext, norm (ob(k).center) + ob(k).radius);
      case "plane"
        ext = max (ext, norm (ob(k).point));
      case "mesh"
        ext = max (ext, max (sqrt (sum (double (ob(k).vertices) .^ 2, 2))));
    endswitch
  endfor
  ext += norm (cam.eye);
  s = sprintf ("light_source { %s color rgb 1 parallel point_at <0, 0, 0> }\n",
               vec (L * 1000 * ext));
endfunction

## the average of the tables, times their number: their sum
function s = texture_sdl (q)
  fin = sprintf ("finish { ambient 0 emission 0 diffuse %d brilliance 1 specular 0 phong 0 reflection 0 }",
                 max (numel (q), 1));
  if (isempty (q))
    pig = "pigment { rgb 0 }";
  elseif (numel (q) == 1)
    pig = sprintf ("pigment { Lf_term%d }", q);
  else
    pig = ["pigment { average pigment_map {", sprintf(" [1 Lf_term%d]", q), " } }"];
  endif
  s = sprintf ("// POV-Ray applies max(cos ti, 0) and the shadows\n#declare Lf_tex = texture { %s %s }\n",
               pig, fin);
endfunction

function [s, nfd] = objects_sdl (ob, keep, faces)
  parts = {};
  nfd = 0;
  for k = 1:numel (ob)
    if (! keep(k))
      if (strcmp (ob(k).type, "mesh"))
        nfd += rows (ob(k).faces);
      endif
      continue;
    endif
    switch (ob(k).type)
      case "sphere"
        parts{end+1} = sprintf ("sphere { %s, %.12g texture { Lf_tex } }\n",
                                vec (ob(k).center), ob(k).radius);
      case "plane"
        nn = double (ob(k).normal(:)');
        nn /= norm (nn);
        parts{end+1} = sprintf ("plane { %s, %.12g texture { Lf_tex } }\n", vec (nn),
                                nn * double (ob(k).point(:)));
      case "mesh"
        fc = double (ob(k).faces);
        if (! isempty (faces{k}))
          nfd += nnz (! faces{k});
          fc = fc(faces{k},:);
        endif
        [used, ~, j] = unique (fc(:));
        fc = reshape (j, size (fc)) - 1;
        vx = double (ob(k).vertices(used,:));
        p = {sprintf("mesh2 {\n vertex_vectors { %d,\n", rows (vx)), ...
             sprintf("<%.9g,%.9g,%.9g>\n", vx')};
        if (! isempty (ob(k).normals))
          nv = double (ob(k).normals(used,:));
          p(end+1:end+2) = {sprintf(" }\n normal_vectors { %d,\n", rows (nv)), ...
                            sprintf("<%.9g,%.9g,%.9g>\n", nv')};
        endif
        p(end+1:end+3) = {sprintf(" }\n face_indices { %d,\n", rows (fc)), ...
                          sprintf("<%d,%d,%d>\n", fc'), " }\n texture { Lf_tex }\n}\n"};
        parts{end+1} = [p{:}];
    endswitch
  endfor
  s = [parts{:}];
endfunction
