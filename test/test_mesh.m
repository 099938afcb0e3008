## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## Integration tests of meshes as users have them: mesh_read on every PLY
## encoding and every OBJ face form, per-corner normals, degenerate
## triangles, malformed files (a deterministic fuzz of about 450 mutated
## files), and the framing of scene_make ("mesh", "file", ...).  Run from the
## package root with
##   addpath ("inst"); test ("test/test_mesh.m")
## The Happy Buddha test uses ../shared/data/meshes/happy-buddha.obj (beside
## the project, or beside LAFORTUNE_TOP) and skips with a message when absent.

%!function put (f, b)
%!  fid = fopen (f, "w");
%!  fwrite (fid, b, "uint8");
%!  fclose (fid);
%!endfunction

%!function b = get (f)
%!  fid = fopen (f, "r");
%!  b = fread (fid, Inf, "uint8=>uint8").';
%!  fclose (fid);
%!endfunction

%!function [V, P, F, N] = pyramid ()
%!  ## a square pyramid: the base quad first, then 4 triangles
%!  V = [0 0 0; 1 0 0; 1 0 1; 0 0 1; 0.5 1 0.5];
%!  P = {[1 2 3 4], [1 2 5], [2 3 5], [3 4 5], [4 1 5]};
%!  F = [1 2 3; 1 3 4; 1 2 5; 2 3 5; 3 4 5; 4 1 5];
%!  N = [-1 -1 -1; 1 -1 -1; 1 -1 1; -1 -1 1; 0 2 0];
%!endfunction

%!function s = obj_text (V, P, N, form, rel)
%!  ## OBJ with corners "v", "vt", "vn" or "vtn"; REL: negative indices
%!  s = sprintf ("# test mesh\nv %g %g %g\n", V.');
%!  s = [s sprintf("vt %g %g\n", V(:,[1 3]).')];
%!  if (! isempty (N))
%!    s = [s sprintf("vn %g %g %g\n", N.')];
%!  endif
%!  s = [s "g pyramid\nusemtl stone\ns off\n"];
%!  for k = 1:numel (P)
%!    i = P{k};
%!    if (rel)
%!      i = i - rows (V) - 1;
%!    endif
%!    switch (form)
%!      case "v"
%!        c = sprintf (" %d", i);
%!      case "vt"
%!        c = sprintf (" %d/%d", [i; i]);
%!      case "vn"
%!        c = sprintf (" %d//%d", [i; i]);
%!      case "vtn"
%!        c = sprintf (" %d/%d/%d", [i; i; i]);
%!    endswitch
%!    s = [s "f" c "\n"];
%!  endfor
%!endfunction

%!function write_ply (f, fmt, V, P, N)
%!  ## PLY with x y z (float), [nx ny nz], an extra property and element
%!  fid = fopen (f, "w");
%!  fprintf (fid, "ply\nformat %s 1.0\ncomment test\nelement vertex %d\n", fmt, rows (V));
%!  fprintf (fid, "property float x\nproperty float y\nproperty float z\n");
%!  if (! isempty (N))
%!    fprintf (fid, "property float nx\nproperty float ny\nproperty float nz\n");
%!  endif
%!  fprintf (fid, "property uchar red\nelement face %d\n", numel (P));
%!  fprintf (fid, "property list uchar int vertex_indices\nelement edge 1\n");
%!  fprintf (fid, "property int v1\nproperty int v2\nend_header\n");
%!  X = [V N];
%!  if (strcmp (fmt, "ascii"))
%!    fprintf (fid, [repmat("%g ", 1, columns (X)) "7\n"], X.');
%!    for k = 1:numel (P)
%!      fprintf (fid, "%d%s\n", numel (P{k}), sprintf (" %d", P{k} - 1));
%!    endfor
%!    fprintf (fid, "0 1\n");
%!  else
%!    arch = "ieee-le";
%!    if (strcmp (fmt, "binary_big_endian"))
%!      arch = "ieee-be";
%!    endif
%!    for i = 1:rows (X)
%!      fwrite (fid, X(i,:), "float32", 0, arch);
%!      fwrite (fid, 7, "uint8", 0, arch);
%!    endfor
%!    for k = 1:numel (P)
%!      fwrite (fid, numel (P{k}), "uint8", 0, arch);
%!      fwrite (fid, P{k} - 1, "int32", 0, arch);
%!    endfor
%!    fwrite (fid, [0 1], "int32", 0, arch);
%!  endif
%!  fclose (fid);
%!endfunction

%!function arch = ifelse_arch (fmt)
%!  arch = "ieee-le";
%!  if (strcmp (fmt, "binary_big_endian"))
%!    arch = "ieee-be";
%!  endif
%!endfunction

%!function check_mesh (V, F, N, info)
%!  ## what every mesh from mesh_read satisfies
%!  assert (columns (V) == 3 && rows (V) >= 1 && all (isfinite (V(:))));
%!  assert (columns (F) == 3 && rows (F) >= 1);
%!  assert (all (F(:) == fix (F(:))) && all (F(:) >= 1) && all (F(:) <= rows (V)));
%!  assert (isempty (N) || isequal (size (N), size (V)));
%!  if (! isempty (N))
%!    len = sqrt (sum (N .^ 2, 2));
%!    assert (all (abs (len - 1) < 1e-6 | len == 0));
%!  endif
%!  c = cross (V(F(:,2),:) - V(F(:,1),:), V(F(:,3),:) - V(F(:,1),:), 2);
%!  assert (all (sqrt (sum (c .^ 2, 2)) > 0));
%!  assert ([info.vertices info.faces], [rows(V) rows(F)]);
%!  assert (info.triangles - info.degenerate, rows (F));
%!endfunction

%!function [id, msg] = read_error (f)
%!  id = "";
%!  msg = "";
%!  try
%!    mesh_read (f);
%!  catch e
%!    id = e.identifier;
%!    msg = e.message;
%!  end_try_catch
%!endfunction

%!function [x, y, z] = view_coords (s, V)
%!  ## camera frame coordinates: x right, y up, z toward the target
%!  f = s.camera.target - s.camera.eye; f /= norm (f);
%!  r = cross (f, s.camera.up); r /= norm (r);
%!  u = cross (r, f);
%!  P = V - s.camera.eye;
%!  x = P * r.';  y = P * u.';  z = P * f.';
%!endfunction

%!function [rows_hit, cols_hit] = coverage (s)
%!  ## pixels where the mesh is seen: a grey diffuse surface lit from the camera
%!  s.light.direction = (s.camera.eye - s.camera.target) / norm (s.camera.eye - s.camera.target);
%!  s.background = [0 0 0];
%!  m = struct ("rho_d", [0.5 0.5 0.5], "Cxy", [0 0 0], "Cz", [0 0 0], "e", [1 1 1]);
%!  img = rt_render (s, m, "progress", false);
%!  hit = any (img > 0, 3);
%!  rows_hit = find (any (hit, 2));
%!  cols_hit = find (any (hit, 1));
%!endfunction

%!shared d
%! d = tempname ();
%! mkdir (d);

%!test
%! ## every encoding of the same pyramid gives the same mesh
%! [V0, P, F0, N0] = pyramid ();
%! Nu = N0 ./ sqrt (sum (N0 .^ 2, 2));
%! cases = {};
%! for form = {"v", "vt", "vn", "vtn"}
%!   for rel = [false true]
%!     f = fullfile (d, sprintf ("p_%s_%d.obj", form{1}, rel));
%!     nn = any (strcmp (form{1}, {"vn", "vtn"}));
%!     put (f, obj_text (V0, P, N0(:, 1:3*nn), form{1}, rel));
%!     cases(end+1,:) = {f, nn, "obj"};
%!   endfor
%! endfor
%! for fmt = {"ascii", "binary_little_endian", "binary_big_endian"}
%!   for nn = [false true]
%!     f = fullfile (d, sprintf ("p_%s_%d.ply", fmt{1}, nn));
%!     write_ply (f, fmt{1}, V0, P, N0(:, 1:3*nn));
%!     cases(end+1,:) = {f, nn, ["ply " fmt{1}]};
%!   endfor
%! endfor
%! assert (rows (cases), 14);
%! for k = 1:rows (cases)
%!   [V, F, N, info] = mesh_read (cases{k,1});
%!   check_mesh (V, F, N, info);
%!   assert (V, V0, 0);
%!   assert (F, F0, 0);
%!   assert (info.format, cases{k,3});
%!   assert ([info.polygons info.triangles info.degenerate info.split], [5 6 0 0]);
%!   if (cases{k,2})
%!     assert (N, Nu, 1e-7);
%!     assert (info.normals, "vertex");
%!   else
%!     assert (isempty (N));
%!     assert (info.normals, "none");
%!   endif
%! endfor

%!test
%! ## PLY faces of varying length with other properties around the list,
%! ## a 2-byte count, in every encoding (the record-by-record path)
%! V = [0 0 0; 1 0 0; 1 1 0; 0 1 0; 0.5 1.5 0; -0.5 0.5 0];
%! P = {[1 2 3 4], [1 4 6], [2 3 5 4 1]};
%! Fq = [1 2 3; 1 3 4; 1 4 6; 2 3 5; 2 5 4; 2 4 1];
%! for fmt = {"ascii", "binary_little_endian", "binary_big_endian"}
%!   f = fullfile (d, ["var_" fmt{1} ".ply"]);
%!   fid = fopen (f, "w");
%!   fprintf (fid, "ply\nformat %s 1.0\nelement vertex 6\nproperty double x\n", fmt{1});
%!   fprintf (fid, "property double y\nproperty double z\nelement face 3\nproperty uchar flags\n");
%!   fprintf (fid, "property list ushort uint vertex_indices\nproperty float quality\nend_header\n");
%!   if (strcmp (fmt{1}, "ascii"))
%!     fprintf (fid, "%g %g %g\n", V.');
%!     for k = 1:3
%!       fprintf (fid, "%d %d%s 0.5\n", k, numel (P{k}), sprintf (" %d", P{k} - 1));
%!     endfor
%!   else
%!     arch = ifelse_arch (fmt{1});
%!     fwrite (fid, V.', "float64", 0, arch);
%!     for k = 1:3
%!       fwrite (fid, k, "uint8", 0, arch);
%!       fwrite (fid, numel (P{k}), "uint16", 0, arch);
%!       fwrite (fid, P{k} - 1, "uint32", 0, arch);
%!       fwrite (fid, 0.5, "float32", 0, arch);
%!     endfor
%!   endif
%!   fclose (fid);
%!   [W, F, ~, info] = mesh_read (f);
%!   assert (W, V);
%!   assert (F, Fq);
%!   assert ([info.polygons info.triangles], [3 6]);
%!   ## a bad count in the middle, and the data cut short
%!   b = get (f);
%!   if (strcmp (fmt{1}, "ascii"))
%!     put (f, strrep (char (b), "2 3 0 3 5", "2 -3 0 3 5"));
%!     assert (read_error (f), "lafortune:meshReadFormat");
%!   endif
%!   put (f, b(1:end-6));
%!   assert (read_error (f), "lafortune:meshReadTruncated");
%! endfor

%!test
%! ## a hexagon is a fan around its first corner; comments anywhere
%! f = fullfile (d, "hex.obj");
%! a = (0:5)' * pi / 3;
%! put (f, [sprintf("v %.17g %.17g 0  # corner\n", [cos(a) sin(a)].') ...
%!          "f 1 2 3 4 5 6 # the face\n# f 1 2 7\n"]);
%! [V, F, N, info] = mesh_read (f);
%! assert (F, [1 2 3; 1 3 4; 1 4 5; 1 5 6]);
%! assert ([info.polygons info.triangles], [1 4]);

%!test
%! ## per-corner normals that differ: a flat-shaded cube, vertices split
%! [x, y, z] = ndgrid (0:1, 0:1, 0:1);
%! V = [x(:) y(:) z(:)];                        # vertex i: bits of i-1
%! Q = [1 3 4 2; 5 6 8 7; 1 2 6 5; 3 7 8 4; 1 5 7 3; 2 4 8 6];
%! Nf = [0 0 -1; 0 0 1; 0 -1 0; 0 1 0; -1 0 0; 1 0 0];
%! s = sprintf ("v %d %d %d\n", V.');
%! s = [s sprintf("vn %d %d %d\n", Nf.')];
%! for k = 1:6
%!   s = [s sprintf("f %d//%d %d//%d %d//%d %d//%d\n", [Q(k,:); k k k k])];
%! endfor
%! f = fullfile (d, "cube.obj");
%! put (f, s);
%! [W, F, N, info] = mesh_read (f);
%! check_mesh (W, F, N, info);
%! assert (info.normals, "corner");
%! assert (info.split, 16);                     # 8 vertices x 3 normals = 24
%! assert (size (W), [24 3]);
%! assert (W(1:8,:), V);                        # the file's vertices first
%! assert (rows (unique (W, "rows")), 8);       # copies of them after
%! ## every triangle: the same normal at its corners, the face's own
%! fn = cross (W(F(:,2),:) - W(F(:,1),:), W(F(:,3),:) - W(F(:,1),:), 2);
%! fn ./= sqrt (sum (fn .^ 2, 2));
%! for c = 1:3
%!   assert (N(F(:,c),:), fn, 1e-12);
%! endfor
%! ## equal normals under different indices (one vn per corner): no split
%! s = sprintf ("v %d %d %d\n", V.');
%! Vn = V - 0.5;
%! s = [s sprintf("vn %g %g %g\n", repmat (Vn, 3, 1).')];   # 24 vn, 3 per vertex
%! for k = 1:6
%!   s = [s sprintf("f %d//%d %d//%d %d//%d %d//%d\n", ...
%!                  [Q(k,:); Q(k,:) + 8 * mod(k, 3)])];
%! endfor
%! put (f, s);
%! [W, F, N, info] = mesh_read (f);
%! assert (info.normals, "vertex");
%! assert (info.split, 0);
%! assert (W, V);
%! assert (N, Vn ./ sqrt (sum (Vn .^ 2, 2)), 1e-12);

%!test
%! ## rendered, the split flat-shaded cube looks exactly like the cube
%! ## without normals (shaded with its face normals); averaging the corner
%! ## normals would round it
%! a = 0.5;  b = 0.7;
%! R = [1 0 0; 0 cos(a) -sin(a); 0 sin(a) cos(a)] * [cos(b) 0 sin(b); 0 1 0; -sin(b) 0 cos(b)];
%! [x, y, z] = ndgrid (0:1, 0:1, 0:1);
%! V = ([x(:) y(:) z(:)] - 0.5) * R.';
%! Q = [1 3 4 2; 5 6 8 7; 1 2 6 5; 3 7 8 4; 1 5 7 3; 2 4 8 6];
%! Nf = [0 0 -1; 0 0 1; 0 -1 0; 0 1 0; -1 0 0; 1 0 0] * R.';
%! f = fullfile (d, "cube_n.obj");
%! g = fullfile (d, "cube_0.obj");
%! s = sprintf ("v %.17g %.17g %.17g\n", V.');
%! t = [s sprintf("vn %.17g %.17g %.17g\n", Nf.')];
%! for k = 1:6
%!   t = [t sprintf("f %d//%d %d//%d %d//%d %d//%d\n", [Q(k,:); k k k k])];
%!   s = [s sprintf("f %d %d %d %d\n", Q(k,:))];
%! endfor
%! put (f, t);
%! put (g, s);
%! m = struct ("rho_d", [0.3 0.3 0.3], "Cxy", [-1 -1 -1], "Cz", [1 1 1], "e", [20 20 20]);
%! sn = scene_make ("mesh", "file", f, "size", [24 24], "spp", 1, "light_direction", [-1 2 3]);
%! s0 = scene_make ("mesh", "file", g, "size", [24 24], "spp", 1, "light_direction", [-1 2 3]);
%! assert (sn.mesh_info.split, 16);
%! assert (isempty (s0.objects.normals));
%! a = rt_render (sn, m, "progress", false);
%! b = rt_render (s0, m, "progress", false);
%! assert (nnz (any (a > 0, 3)) > 100);
%! assert (a, b, 1e-9 * max (b(:)));

%!test
%! ## normals on some corners only: ignored, stated in info
%! f = fullfile (d, "partial.obj");
%! put (f, "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\nf 2 4 3\n");
%! [V, F, N, info] = mesh_read (f);
%! assert (isempty (N));
%! assert (info.normals, "ignored");
%! assert (F, [1 2 3; 2 4 3]);

%!test
%! ## degenerate triangles: repeated index, collinear, coincident corners
%! f = fullfile (d, "degen.obj");
%! put (f, ["v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0.5 0 0\nv 0 0 0\nv 1 1 0\n" ...
%!          "f 1 2 3\nf 1 1 2\nf 1 4 2\nf 1 5 3\nf 2 6 3\nf 1 2 2 3\n"]);
%! [V, F, N, info] = mesh_read (f);
%! check_mesh (V, F, N, info);
%! ## the quad 1 2 2 3 fans into (1 2 2) dropped and (1 2 3) kept
%! assert (F, [1 2 3; 2 6 3; 1 2 3]);
%! assert ([info.triangles info.degenerate info.faces], [7 4 3]);
%! ## the same in a binary PLY
%! g = fullfile (d, "degen.ply");
%! write_ply (g, "binary_little_endian", V, {[1 2 3], [1 1 2], [1 4 2], [1 5 3], [2 6 3], [1 2 2 3]}, []);
%! [V2, F2, ~, info2] = mesh_read (g);
%! assert (F2, F);
%! assert (info2.degenerate, 4);
%! ## scene_make shows the count
%! s = scene_make ("mesh", "file", f, "size", [16 16]);
%! assert (s.mesh_info.degenerate, 4);
%! assert (rows (s.objects.faces), 3);
%! ## nothing but degenerate triangles: an error
%! put (f, "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\nf 1 1 2\n");
%! assert (read_error (f), "lafortune:meshReadCount");

%!test
%! ## a zero-length normal is replaced by the mean of the faces around it
%! f = fullfile (d, "zn.ply");
%! V = [0 0 0; 1 0 0; 0 1 0; 0 0 1];
%! write_ply (f, "ascii", V, {[1 3 2], [1 2 4]}, [0 0 0; 0 0 -1; 0 0 -1; 0 -1 0]);
%! [~, ~, N, info] = mesh_read (f);
%! assert (info.filled, 1);
%! assert (N(1,:), [0 -1 -1] / sqrt (2), 1e-12);

%!test
%! ## errors with identifiers
%! f = fullfile (d, "e.obj");
%! put (f, "v 0 0 0\nv 1 nan 0\nv 0 1 0\nf 1 2 3\n");
%! assert (read_error (f), "lafortune:meshReadFormat");
%! put (f, "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/2 3/1\n");
%! assert (read_error (f), "lafortune:meshReadIndex");
%! put (f, "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//-2\n");
%! assert (read_error (f), "lafortune:meshReadIndex");
%! put (f, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n");
%! assert (read_error (f), "lafortune:meshReadIndex");
%! put (f, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3/\n");
%! assert (read_error (f), "lafortune:meshReadFormat");
%! put (f, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3.5\n");
%! assert (read_error (f), "lafortune:meshReadFormat");
%! g = fullfile (d, "e.ply");
%! write_ply (g, "ascii", [0 0 0; 1 0 0; 0 1 0], {[1 2 3]}, [0 0 1; 0 0 1; NaN 0 1]);
%! assert (read_error (g), "lafortune:meshReadFormat");
%! write_ply (g, "ascii", [0 0 0; 1 0 0; 0 1 0], {[1 2 3]}, []);
%! b = get (g);
%! put (g, [b(1:20) uint8([200 1 255]) b(21:end)]);   # binary junk in the header
%! [id, msg] = read_error (g);
%! assert (id, "lafortune:meshReadFormat");
%! assert (! isempty (strfind (msg, "printable ASCII")));
%! t = strrep (char (b), "property float y", "property float x");
%! put (g, t);
%! assert (read_error (g), "lafortune:meshReadFormat");   # two properties x
%! t = strrep (char (b), "list uchar int", "list float int");
%! put (g, t);
%! assert (read_error (g), "lafortune:meshReadFormat");   # a float list count
%! t = strrep (char (b), "element face 1", "element face 99999999999");
%! put (g, t);
%! assert (read_error (g), "lafortune:meshReadTruncated");
%! write_ply (g, "binary_big_endian", [0 0 0; 1 0 0; 0 1 0], {[1 2 3]}, []);
%! t = strrep (char (get (g)), "element face 1", "element face 4000000000");
%! put (g, t);
%! assert (read_error (g), "lafortune:meshReadTruncated");

%!test
%! ## fuzz: mutated small valid files load into a valid mesh or fail with a
%! ## lafortune: identifier; deterministic (fixed seed)
%! [V0, P, ~, N0] = pyramid ();
%! base = {};
%! base{end+1} = {uint8(obj_text (V0, P, N0, "vtn", false)), ".obj"};
%! base{end+1} = {uint8(obj_text (V0, P, [], "v", true)), ".obj"};
%! fmts = {"ascii", "ascii", "binary_little_endian", "binary_big_endian"};
%! for k = 1:4
%!   f = fullfile (d, "base.ply");
%!   write_ply (f, fmts{k}, V0, P, N0(:, 1:3*(k != 2)));
%!   base{end+1} = {get(f), ".ply"};
%! endfor
%! rand ("twister", 20261122);
%! nper = 75;                                     # 6 x 75 = 450 files
%! nkind = 9;
%! nok = nerr = 0;
%! outcome = zeros (numel (base), nkind);         # errors per base and kind
%! for k = 1:numel (base) * nper
%!   ib = mod (k - 1, numel (base)) + 1;
%!   kind = mod (floor ((k - 1) / numel (base)), nkind) + 1;
%!   b = base{ib}{1};
%!   n = numel (b);
%!   he = strfind (char (b), "end_header");        # PLY: end of the header
%!   if (isempty (he))
%!     he = round (n / 3);
%!   endif
%!   pick = @(lo, hi) lo + floor (rand () * (hi - lo + 1));
%!   junk = @(m) uint8 (floor (rand (1, m) * 256));
%!   switch (kind)
%!     case 1                                     # byte flips
%!       for j = 1:pick (1, 3)
%!         b(pick (1, n)) = junk (1);
%!       endfor
%!     case 2                                     # truncation
%!       b = b(1:pick (0, n - 1));
%!     case 3                                     # binary junk in the header
%!       p = pick (1, he);
%!       b = [b(1:p) junk(pick (1, 8)) b(p+1:end)];
%!     case 4                                     # binary junk in the body
%!       p = pick (he, n);
%!       b = [b(1:p) uint8(128 + floor (rand (1, pick (1, 8)) * 128)) b(p+1:end)];
%!     case 5                                     # a count or index made huge, odd or negative
%!       isd = b >= 48 & b <= 57;
%!       st = find (isd & [true, ! isd(1:end-1)]);
%!       en = find (isd & [! isd(2:end), true]);
%!       i = pick (1, numel (st));
%!       r = {"99999999999", "4294967295", "2147483648", "-1", "0", "1e30", "-7"};
%!       b = [b(1:st(i)-1) uint8(r{pick(1, numel (r))}) b(en(i)+1:end)];
%!     case 6                                     # a line dropped
%!       nl = find (b == 10);
%!       i = pick (1, numel (nl) - 1);
%!       b = [b(1:nl(i)) b(nl(i+1)+1:end)];
%!     case 7                                     # a line repeated
%!       nl = find (b == 10);
%!       i = pick (1, numel (nl) - 1);
%!       b = [b(1:nl(i+1)) b(nl(i)+1:end)];
%!     case 8                                     # a stretch zeroed
%!       p = pick (1, n);
%!       b(p:min (n, p + pick (1, 16))) = 0;
%!     case 9                                     # two lines swapped
%!       nl = [0 find(b == 10)];
%!       i = pick (1, numel (nl) - 2);
%!       b = [b(1:nl(i)) b(nl(i+1)+1:nl(i+2)) b(nl(i)+1:nl(i+1)) b(nl(i+2)+1:end)];
%!   endswitch
%!   f = fullfile (d, sprintf ("fuzz%03d%s", k, base{ib}{2}));
%!   put (f, b);
%!   try
%!     [V, F, N, info] = mesh_read (f);
%!     ok = true;
%!   catch e
%!     ok = false;
%!     if (! strncmp (e.identifier, "lafortune:", 10))
%!       error ("fuzz file %d (base %d, mutation %d): error without a lafortune: id: [%s] %s",
%!              k, ib, kind, e.identifier, e.message);
%!     endif
%!   end_try_catch
%!   if (ok)
%!     check_mesh (V, F, N, info);
%!     nok++;
%!   else
%!     nerr++;
%!     outcome(ib, kind)++;
%!   endif
%!   delete (f);
%! endfor
%! assert (nok + nerr, 450);
%! ## both outcomes occur, and junk in ASCII PLY headers (the old
%! ## "invalid UTF-8" failure) was exercised and rejected
%! assert (nok > 0 && nerr > 0);
%! assert (all (outcome([3 4], 3) > 0));

%!test
%! ## framing: a small mesh far from the origin
%! f = fullfile (d, "far.obj");
%! [V0, P] = pyramid ();
%! Vf = V0 .* [1 3 0.5] * 0.01 + [100 -50 30];   # 0.01 x 0.03 x 0.005 at (100, -50, 30)
%! put (f, obj_text (Vf, P, [], "v", false));
%! ## default: centred, largest side 2; mesh_info maps back to the file
%! s = scene_make ("mesh", "file", f, "size", "paper");
%! V = s.objects.vertices;
%! assert ((min (V) + max (V)) / 2, [0 0 0], 1e-12);
%! assert (max (max (V) - min (V)), 2, 1e-12);
%! mi = s.mesh_info;
%! assert ((Vf * mi.rotation.' - mi.center) * mi.scale, V, 1e-9);
%! assert ([s.camera.eye; s.camera.target], [0 0 5; 0 0 0], 1e-12);
%! ## normalize false: the file's coordinates, the camera fitted to them
%! for cam = {"orthographic", "perspective"}
%!   s = scene_make ("mesh", "file", f, "size", [40 24], "spp", 1,
%!                   "normalize", false, "camera", cam{1});
%!   assert (s.objects.vertices, Vf);
%!   assert (s.camera.target, (min (Vf) + max (Vf)) / 2, 1e-12);
%!   [x, y, z] = view_coords (s, Vf);
%!   assert (all (z > 0));                         # the eye is outside the box
%!   if (strcmp (cam{1}, "orthographic"))
%!     hy = s.camera.extent / 2;
%!     fill = max (abs (y)) / hy;
%!     assert (max (abs (x)) <= hy * 24 / 40);
%!   else
%!     ty = tand (s.camera.fov / 2);
%!     fill = max (abs (y) ./ z) / ty;
%!     assert (max (abs (x) ./ z) <= ty * 24 / 40);
%!   endif
%!   assert (fill > 0.85 && fill <= 1 / 1.1 + 1e-12);   # fills, with a margin
%!   ## rendered: the mesh is seen, fills the height, not cut by the frame
%!   [r, c] = coverage (s);
%!   assert (numel (r) >= 0.8 * 40);
%!   assert (r(1) > 1 && r(end) < 40 && c(1) > 1 && c(end) < 24);
%!   ## a point light keeps its distance in units of the mesh
%!   sp = scene_make ("mesh", "file", f, "normalize", false, "light", "point");
%!   assert (norm (sp.light.position - sp.camera.target), 5 * 0.03, 1e-12);
%! endfor

%!test
%! ## "up", "z": the mesh's z becomes the world's y, its -y side faces the camera
%! f = fullfile (d, "zup.ply");
%! [V0, P, ~, N0] = pyramid ();
%! Vz = V0(:, [1 3 2]) .* [1 1 3];                 # apex along +z, 3 tall
%! Vz(:,2) -= 0.2 * (Vz(:,3) > 1);                 # the apex leans to -y
%! Nz = N0(:, [1 3 2]);
%! write_ply (f, "binary_little_endian", Vz, P, Nz);
%! s = scene_make ("mesh", "file", f, "up", "z", "size", [32 32]);
%! V = s.objects.vertices;
%! assert (s.mesh_info.up, "z");
%! [~, iy] = max (V(:,2));
%! assert (iy, 5);                                 # the apex is on top
%! assert (max (V(:,2)) - min (V(:,2)), 2, 1e-12);  # the tall side is y
%! assert (V(5,3) > mean (V(1:4,3)));              # leaning toward the camera
%! Nu = Nz ./ sqrt (sum (Nz .^ 2, 2));
%! assert (s.objects.normals, Nu * s.mesh_info.rotation.', 1e-7);
%! assert (det (s.mesh_info.rotation), 1);
%! ## the same mesh read as y up lies on its side
%! t = scene_make ("mesh", "file", f, "size", [32 32]);
%! assert (max (t.objects.vertices(:,3)) - min (t.objects.vertices(:,3)), 2, 1e-12);

%!error <UP must be> scene_make ("mesh", "file", "x.obj", "up", "x")
%!error <for a mesh read from a FILE> scene_make ("torus", "up", "z")
%!error <for a mesh read from a FILE> scene_make ("mesh", "normalize", false)
%!error <NORMALIZE must be> scene_make ("mesh", "file", "x.obj", "normalize", "yes")

%!test
%! ## the Happy Buddha (y up, 100k triangles): the defaults frame it for the
%! ## paper's 256 wide x 512 high image
%! top = getenv ("LAFORTUNE_TOP");
%! if (isempty (top))
%!   top = pwd ();
%! endif
%! f = fullfile (top, "..", "shared", "data", "meshes", "happy-buddha.obj");
%! if (! exist (f, "file"))
%!   printf ("skipped: %s absent\n", f);
%!   return;
%! endif
%! s = scene_make ("mesh", "file", f, "size", "paper", "spp", 1);
%! mi = s.mesh_info;
%! assert ([mi.vertices mi.faces mi.degenerate], [49950 100000 0]);
%! assert ([mi.format "," mi.normals], "obj,none");
%! assert ([s.camera.eye; s.camera.target], [0 0 5; 0 0 0], 1e-12);
%! assert (s.camera.extent, 2.2, 1e-12);
%! V = s.objects.vertices;
%! assert (max (V(:,2)) - min (V(:,2)), 2, 1e-12);   # the tall side, y up
%! ## rendered at a quarter of the paper's size (the framing does not depend
%! ## on the resolution): the figure fills 9/10 of the height, inside the frame
%! s.height = 128;
%! s.width = 64;
%! [r, c] = coverage (s);
%! assert (numel (r) >= 0.85 * 128);
%! assert (r(1) > 1 && r(end) < 128 && c(1) > 1 && c(end) < 64);
%! assert (numel (c) >= 0.5 * 64);

%!test
%! confirm_recursive_rmdir (false, "local");
%! rmdir (d, "s");
