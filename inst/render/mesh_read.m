## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {lafortune} {[@var{V}, @var{F}, @var{N}] =} mesh_read (@var{file})
## @deftypefnx {lafortune} {[@var{V}, @var{F}, @var{N}, @var{info}] =} mesh_read (@var{file})
## Read a triangle mesh from a PLY or Wavefront OBJ file.
##
## @var{V} is the V x 3 array of vertex positions, @var{F} the F x 3 array of
## 1-based vertex indices (polygons are fan-triangulated: a polygon
## v1 v2 @dots{} vn gives the triangles (v1, vk, vk+1), k = 2 @dots{} n-1) and
## @var{N} the V x 3 array of unit vertex normals, or empty when the file has
## none.
##
## @strong{PLY}: @code{ascii 1.0}, @code{binary_little_endian 1.0} and
## @code{binary_big_endian 1.0}.  The element @code{vertex} must have the
## properties @code{x}, @code{y}, @code{z} (any scalar type) and may have
## @code{nx}, @code{ny}, @code{nz}; other properties and other elements are
## skipped.  Faces are the list property @code{vertex_indices} (or
## @code{vertex_index}) of the element @code{face} (0-based).  The header
## must be printable ASCII.
##
## @strong{OBJ}: lines @code{v x y z [w]}, @code{vt}, @code{vn x y z} and
## @code{f} with corners in the forms @code{v}, @code{v/vt}, @code{v//vn}
## and @code{v/vt/vn}; negative indices count back from the last vertex
## (texture coordinate, normal) read so far; @code{#} starts a comment.
## Texture coordinates are checked but not returned.  Normals: when every
## face corner has one, a vertex that all its corners give the same normal
## (after normalisation) gets it; a vertex whose corners give different
## normals (a crease, a flat-shaded face) is @emph{split}: one copy of the
## vertex per distinct normal, the copies appended after the file's
## vertices, so that the surface is shaded as the file says.  When only some
## corners have a normal the normals are ignored and @var{N} is empty.
## Other statements (@code{g}, @code{o}, @code{usemtl}, @code{s} @dots{})
## are ignored.
##
## @strong{Clean-up}: triangles with a repeated vertex index or zero area
## (collinear or coincident corners: |AB x AC| <= 4 eps |AB| |AC|) are
## dropped.  Normals are scaled to unit length; a zero-length one is replaced
## by the area-weighted mean of the normals of the triangles around the
## vertex.
##
## @var{info} is a struct with the fields @code{file}, @code{format}
## (@qcode{"obj"}, @qcode{"ply ascii"}, @qcode{"ply binary_little_endian"}
## or @qcode{"ply binary_big_endian"}), @code{polygons} (faces in the file),
## @code{triangles} (after fan triangulation), @code{degenerate} (triangles
## dropped), @code{faces} (rows of @var{F}), @code{vertices} (rows of
## @var{V}), @code{normals} (@qcode{"none"}, @qcode{"vertex"},
## @qcode{"corner"}: per-corner normals, vertices split, or
## @qcode{"ignored"}), @code{split} (vertices added by splitting) and
## @code{filled} (zero-length normals replaced).
##
## The format is taken from the extension (@file{.ply}, @file{.obj}, any
## case), else from the first bytes (@code{ply}).  Nothing is written.
##
## Every malformed file gives an error with one of these identifiers:
## @code{lafortune:meshReadNotFound} (no such file),
## @code{lafortune:meshReadFormat} (unknown format, malformed header or
## line, non-ASCII header, non-finite coordinates or normals),
## @code{lafortune:meshReadTruncated} (less data than the header declares),
## @code{lafortune:meshReadCount} (more data than declared, a face with
## fewer than 3 corners, no vertices, no faces, or only degenerate ones),
## @code{lafortune:meshReadIndex} (a vertex, texture or normal index out of
## range).
##
## @example
## @group
## [V, F, N, info] = mesh_read ("happy_vrip.ply");   # Stanford Happy Buddha
## info.degenerate                                  # triangles dropped
## scene = scene_make ("mesh", "file", "happy_vrip.ply");
## @end group
## @end example
## @seealso{scene_make, mesh_torus, rt_render}
## @end deftypefn

function [V, F, N, info] = mesh_read (file)
  if (nargin != 1)
    print_usage ();
  endif
  if (! ischar (file) || ! isrow (file))
    error ("lafortune:meshReadFormat", "mesh_read: FILE must be a file name (char row)");
  endif
  if (! exist (file, "file") || isfolder (file))
    error ("lafortune:meshReadNotFound", "mesh_read: no such file: %s", file);
  endif
  [fid, msg] = fopen (file, "r");
  if (fid < 0)
    error ("lafortune:meshReadNotFound", "mesh_read: cannot open %s: %s", file, msg);
  endif
  bytes = fread (fid, Inf, "uint8=>uint8").';
  fclose (fid);

  [~, ~, ext] = fileparts (file);
  ext = lower (ext);
  if (strcmp (ext, ".ply") || (! strcmp (ext, ".obj") && numel (bytes) >= 4
                                && all (bytes(1:3) == uint8 ("ply"))
                                && any (bytes(4) == uint8 ([10 13]))))
    [V, F, N, info] = mesh_ply (bytes, file);
  elseif (strcmp (ext, ".obj"))
    [V, F, N, info] = mesh_obj (bytes, file);
  else
    error ("lafortune:meshReadFormat",
           "mesh_read: %s: unknown mesh format (expected a .ply or .obj file)", file);
  endif
  [V, F, N, info] = mesh_finish (V, F, N, info, file);
  info.file = file;
  info = orderfields (info, {"file", "format", "vertices", "faces", "polygons", ...
                             "triangles", "degenerate", "normals", "split", "filled"});
endfunction

%!function write_text (f, s)
%!  fid = fopen (f, "w"); fputs (fid, s); fclose (fid);
%!endfunction

%!function write_ply_binary (f, V, F, big)
%!  fmt = "binary_little_endian";
%!  if (big), fmt = "binary_big_endian"; endif
%!  fid = fopen (f, "w");
%!  fprintf (fid, "ply\nformat %s 1.0\ncomment test\nelement vertex %d\n", fmt, rows (V));
%!  fprintf (fid, "property float x\nproperty float y\nproperty double z\nproperty uchar red\n");
%!  fprintf (fid, "element face %d\nproperty list uchar int vertex_indices\nend_header\n", rows (F));
%!  arch = "ieee-le";
%!  if (big), arch = "ieee-be"; endif
%!  for i = 1:rows (V)
%!    fwrite (fid, V(i,1:2), "float32", 0, arch);
%!    fwrite (fid, V(i,3), "float64", 0, arch);
%!    fwrite (fid, 7, "uint8", 0, arch);
%!  endfor
%!  for i = 1:rows (F)
%!    fwrite (fid, 3, "uint8", 0, arch);
%!    fwrite (fid, F(i,:) - 1, "int32", 0, arch);
%!  endfor
%!  fclose (fid);
%!endfunction

%!shared d, Vq, Fq
%! d = tempname (); mkdir (d);
%! Vq = [0 0 0; 1 0 0; 1 1 0; 0 1 0; 0.5 0.5 1];
%! Fq = [1 2 3; 1 3 4; 1 2 5];

%!test
%! ## ASCII PLY: a quad and a triangle, normals, extra property and element
%! f = fullfile (d, "a.ply");
%! write_text (f, ["ply\nformat ascii 1.0\ncomment x\nelement vertex 5\n" ...
%!   "property float x\nproperty float y\nproperty float z\nproperty float nx\n" ...
%!   "property float ny\nproperty float nz\nproperty uchar red\n" ...
%!   "element face 2\nproperty list uchar int vertex_indices\n" ...
%!   "element edge 1\nproperty int v1\nproperty int v2\nend_header\n" ...
%!   "0 0 0 0 0 2 1\n1 0 0 0 0 1 1\n1 1 0 0 0 1 1\n0 1 0 0 0 1 1\n0.5 0.5 1 0 3 4 1\n" ...
%!   "4 0 1 2 3\n3 0 1 4\n0 1\n"]);
%! [V, F, N] = mesh_read (f);
%! assert (V, Vq);
%! assert (F, Fq);
%! assert (N, [0 0 1; 0 0 1; 0 0 1; 0 0 1; 0 0.6 0.8], 1e-7);

%!test
%! ## binary PLY, both byte orders, mixed property types
%! for big = [false true]
%!   f = fullfile (d, sprintf ("b%d.ply", big));
%!   write_ply_binary (f, Vq, Fq, big);
%!   [V, F, N] = mesh_read (f);
%!   assert (V, Vq);
%!   assert (F, Fq);
%!   assert (isempty (N));
%! endfor

%!test
%! ## binary PLY with varying polygon sizes (general path), vertex_index name
%! f = fullfile (d, "c.ply");
%! fid = fopen (f, "w");
%! fprintf (fid, "ply\nformat binary_little_endian 1.0\nelement vertex 5\n");
%! fprintf (fid, "property float x\nproperty float y\nproperty float z\n");
%! fprintf (fid, "element face 2\nproperty list uchar uint vertex_index\nend_header\n");
%! fwrite (fid, Vq.', "float32");
%! fwrite (fid, 3, "uint8"); fwrite (fid, [0 1 4], "uint32");
%! fwrite (fid, 4, "uint8"); fwrite (fid, [0 1 2 3], "uint32");
%! fclose (fid);
%! [V, F] = mesh_read (f);
%! assert (V, Vq);
%! assert (F, [1 2 5; 1 2 3; 1 3 4]);

%!test
%! ## OBJ: all corner forms, negative indices, a quad, comments, CRLF
%! f = fullfile (d, "a.obj");
%! write_text (f, ["# test\r\nv 0 0 0\r\nv 1 0 0\nv 1 1 0 1.0\n  v 0 1 0\nvt 0 0\n" ...
%!   "vn 0 0 2\nvn 0 0 1\ng grp\nusemtl m\nf 1//1 2//2 3//2 4//2\n" ...
%!   "v 0.5 0.5 1\nvn 0 3 4\nf -5/1/-3 2/1/2 -1/1/-1\n"]);
%! [V, F, N] = mesh_read (f);
%! assert (V, Vq);
%! assert (F, [1 2 3; 1 3 4; 1 2 5]);
%! assert (N, [0 0 1; 0 0 1; 0 0 1; 0 0 1; 0 0.6 0.8], 1e-12);
%! write_text (f, "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nf 1/1 2/2 3/3\nf 1 3 4\n");
%! [V, F, N] = mesh_read (f);
%! assert (F, [1 2 3; 1 3 4]);
%! assert (isempty (N));

%!test
%! ## upper-case extension, magic sniffing without extension
%! f = fullfile (d, "n.PLY");
%! write_ply_binary (f, Vq, Fq, false);
%! assert (mesh_read (f), Vq);
%! g = fullfile (d, "noext");
%! copyfile (f, g);
%! [~, F] = mesh_read (g);
%! assert (F, Fq);

%!error id=lafortune:meshReadNotFound mesh_read ("/nonexistent/mesh.ply")
%!error <Invalid call> mesh_read ()
%!test
%! f = fullfile (d, "x.stl");
%! write_text (f, "solid x\n");
%! fail ("mesh_read (f)", "unknown mesh format");
%!test
%! ## truncated binary and ASCII PLY, OBJ
%! f = fullfile (d, "t.ply");
%! write_ply_binary (f, Vq, Fq, false);
%! fid = fopen (f); b = fread (fid, Inf, "uint8=>uint8"); fclose (fid);
%! fid = fopen (f, "w"); fwrite (fid, b(1:end-5)); fclose (fid);
%! try, mesh_read (f); error ("no error"); catch e, assert (e.identifier, "lafortune:meshReadTruncated"); end
%! write_text (f, "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n");
%! try, mesh_read (f); error ("no error"); catch e, assert (e.identifier, "lafortune:meshReadTruncated"); end
%! write_text (f, "ply\nformat ascii 1.0\nelement vertex 3\n");
%! try, mesh_read (f); error ("no error"); catch e, assert (e.identifier, "lafortune:meshReadFormat"); end
%! g = fullfile (d, "t.obj");
%! write_text (g, "v 0 0 0\nv 1 0\nf 1 2 1\n");
%! try, mesh_read (g); error ("no error"); catch e, assert (e.identifier, "lafortune:meshReadFormat"); end
%!test
%! ## wrong counts: more vertices than declared, a 2-corner face, no faces
%! f = fullfile (d, "w.ply");
%! write_text (f, "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n4 0 1 2 0\n");
%! try, mesh_read (f); error ("no error"); catch e, assert (e.identifier, "lafortune:meshReadCount"); end
%! write_text (f, "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n");
%! try, mesh_read (f); error ("no error"); catch e, assert (e.identifier, "lafortune:meshReadCount"); end
%! g = fullfile (d, "w.obj");
%! write_text (g, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n");
%! try, mesh_read (g); error ("no error"); catch e, assert (e.identifier, "lafortune:meshReadCount"); end
%! write_text (g, "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
%! try, mesh_read (g); error ("no error"); catch e, assert (e.identifier, "lafortune:meshReadCount"); end
%!test
%! ## indices out of range
%! f = fullfile (d, "i.ply");
%! write_ply_binary (f, Vq, [1 2 6], true);
%! try, mesh_read (f); error ("no error"); catch e, assert (e.identifier, "lafortune:meshReadIndex"); end
%! g = fullfile (d, "i.obj");
%! write_text (g, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n");
%! try, mesh_read (g); error ("no error"); catch e, assert (e.identifier, "lafortune:meshReadIndex"); end
%! write_text (g, "v 0 0 0\nv 1 0 0\nf 1 2 -3\nv 0 1 0\n");
%! try, mesh_read (g); error ("no error"); catch e, assert (e.identifier, "lafortune:meshReadIndex"); end
%! write_text (g, "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//2\n");
%! try, mesh_read (g); error ("no error"); catch e, assert (e.identifier, "lafortune:meshReadIndex"); end
%! confirm_recursive_rmdir (false, "local");
%! rmdir (d, "s");

%!test
%! ## info: counts, a degenerate triangle dropped, split normals
%! d = tempname (); mkdir (d);
%! f = fullfile (d, "k.obj");
%! fid = fopen (f, "w");
%! fputs (fid, "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvn 0 0 -1\nvn 0 -1 0\n");
%! fputs (fid, "f 1//1 3//1 2//1\nf 1//2 2//2 4//2\nf 1//2 1//2 2//2\n");
%! fclose (fid);
%! [V, F, N, info] = mesh_read (f);
%! assert ([info.polygons info.triangles info.degenerate info.faces], [3 3 1 2]);
%! assert ([info.vertices info.split], [6 2]);
%! assert (info.normals, "corner");
%! assert (F, [1 3 2; 5 6 4]);
%! assert (V(5:6,:), V(1:2,:));
%! assert (N([1 2 3 4 5 6],:), [0 0 -1; 0 0 -1; 0 0 -1; 0 -1 0; 0 -1 0; 0 -1 0]);
%! delete (f); rmdir (d);

%!demo
%! ## a flat-shaded OBJ cube: each corner of the cube gets three normals,
%! ## so its 8 vertices become 24; the file's degenerate face is dropped
%! f = [tempname() ".obj"];
%! fid = fopen (f, "w");
%! fprintf (fid, "v %d %d %d\n", [0 0 0; 1 0 0; 0 1 0; 1 1 0; 0 0 1; 1 0 1; 0 1 1; 1 1 1].');
%! fprintf (fid, "vn %d %d %d\n", [0 0 -1; 0 0 1; 0 -1 0; 0 1 0; -1 0 0; 1 0 0].');
%! Q = [1 3 4 2; 5 6 8 7; 1 2 6 5; 3 7 8 4; 1 5 7 3; 2 4 8 6];
%! fprintf (fid, "f %d//%d %d//%d %d//%d %d//%d\n", [Q(:,1) (1:6)' Q(:,2) (1:6)' Q(:,3) (1:6)' Q(:,4) (1:6)'].');
%! fprintf (fid, "f 1//1 1//1 2//1\n");
%! fclose (fid);
%! [V, F, N, info] = mesh_read (f)
%! delete (f);
%! trisurf (F, V(:,1), V(:,2), V(:,3)); axis equal;
