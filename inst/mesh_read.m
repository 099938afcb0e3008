## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {lafortune} {[@var{V}, @var{F}, @var{N}] =} mesh_read (@var{file})
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
## @code{vertex_index}) of the element @code{face} (0-based).
##
## @strong{OBJ}: lines @code{v x y z [w]}, @code{vn x y z} and
## @code{f} with corners in the forms @code{v}, @code{v/t}, @code{v/t/n} and
## @code{v//n}; negative indices count back from the last vertex (normal)
## read so far.  Vertex normals are per vertex: a vertex referenced with
## several normals gets their normalised mean; when some face corner has no
## normal, @var{N} is empty.  Other statements (@code{vt}, @code{g},
## @code{usemtl}, comments @dots{}) are ignored.
##
## The format is taken from the extension (@file{.ply}, @file{.obj}, any
## case), else from the first bytes (@code{ply}).  Nothing is written.
##
## Errors (identifiers): @code{lafortune:meshReadNotFound} (no such file),
## @code{lafortune:meshReadFormat} (unknown format, malformed header or
## line), @code{lafortune:meshReadTruncated} (less data than the header
## declares), @code{lafortune:meshReadCount} (more data than declared, a face
## with fewer than 3 corners, no vertices or no faces),
## @code{lafortune:meshReadIndex} (a vertex or normal index out of range).
##
## @example
## @group
## [V, F, N] = mesh_read ("happy_vrip.ply");   # Stanford Happy Buddha
## scene = scene_make ("mesh", "file", "happy_vrip.ply");
## @end group
## @end example
## @seealso{scene_make, mesh_torus, rt_render}
## @end deftypefn

function [V, F, N] = mesh_read (file)
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
    [V, F, N] = read_ply (bytes, file);
  elseif (strcmp (ext, ".obj"))
    [V, F, N] = read_obj (char (bytes), file);
  else
    error ("lafortune:meshReadFormat",
           "mesh_read: %s: unknown mesh format (expected a .ply or .obj file)", file);
  endif
endfunction

## ---------------------------------------------------------------- PLY
function [V, F, N] = read_ply (bytes, file)
  ## header: up to and including the line "end_header"
  hend = strfind (char (bytes(1:min (end, 65536))), "end_header");
  if (numel (bytes) < 4 || ! all (bytes(1:3) == uint8 ("ply")) || isempty (hend))
    error ("lafortune:meshReadFormat",
           "mesh_read: %s: not a PLY file (missing 'ply' magic or 'end_header')", file);
  endif
  p = hend(1) + numel ("end_header");
  while (p <= numel (bytes) && bytes(p) == 13)   # tolerate CR LF
    p++;
  endwhile
  if (p > numel (bytes) || bytes(p) != 10)
    error ("lafortune:meshReadTruncated", "mesh_read: %s: file ends in the PLY header", file);
  endif
  header = strsplit (strrep (char (bytes(1:hend(1)-1)), "\r", ""), "\n");
  body = bytes(p+1:end);

  fmt = "";
  elems = struct ("name", {}, "count", {}, "props", {});
  for k = 2:numel (header)
    w = strsplit (strtrim (header{k}));
    if (isempty (w{1}) || any (strcmp (w{1}, {"comment", "obj_info"})))
      continue;
    endif
    switch (w{1})
      case "format"
        if (numel (w) < 2 || ! any (strcmp (w{2}, {"ascii", "binary_little_endian", ...
                                                   "binary_big_endian"})))
          error ("lafortune:meshReadFormat",
                 "mesh_read: %s: unknown PLY format line '%s' (expected ascii, binary_little_endian or binary_big_endian)",
                 file, header{k});
        endif
        fmt = w{2};
      case "element"
        c = str2double (w(3:end));
        if (numel (w) != 3 || ! isfinite (c) || c < 0 || c != fix (c))
          error ("lafortune:meshReadFormat", "mesh_read: %s: bad PLY line '%s'",
                 file, header{k});
        endif
        elems(end+1) = struct ("name", w{2}, "count", c,
                               "props", struct ("name", {}, "list", {}, "ctype", {},
                                                "type", {}));
      case "property"
        if (isempty (elems))
          error ("lafortune:meshReadFormat",
                 "mesh_read: %s: PLY property before any element", file);
        endif
        if (numel (w) == 5 && strcmp (w{2}, "list"))
          pr = struct ("name", w{5}, "list", true, "ctype", ply_type (w{3}, file),
                       "type", ply_type (w{4}, file));
        elseif (numel (w) == 3)
          pr = struct ("name", w{3}, "list", false, "ctype", "", "type", ply_type (w{2}, file));
        else
          error ("lafortune:meshReadFormat", "mesh_read: %s: bad PLY line '%s'",
                 file, header{k});
        endif
        elems(end).props(end+1) = pr;
      otherwise
        error ("lafortune:meshReadFormat",
               "mesh_read: %s: unknown PLY header line '%s'", file, header{k});
    endswitch
  endfor
  if (isempty (fmt))
    error ("lafortune:meshReadFormat", "mesh_read: %s: PLY header has no format line", file);
  endif
  iv = find (strcmp ({elems.name}, "vertex"), 1);
  jf = find (strcmp ({elems.name}, "face"), 1);
  if (isempty (iv) || isempty (jf))
    error ("lafortune:meshReadCount",
           "mesh_read: %s: PLY file needs a 'vertex' and a 'face' element", file);
  endif
  vn = {elems(iv).props.name};
  if (! all (ismember ({"x", "y", "z"}, vn)))
    error ("lafortune:meshReadFormat",
           "mesh_read: %s: PLY vertex element needs properties x, y, z", file);
  endif
  fl = find (ismember ({elems(jf).props.name}, {"vertex_indices", "vertex_index"})
             & [elems(jf).props.list], 1);
  if (isempty (fl))
    error ("lafortune:meshReadFormat",
           "mesh_read: %s: PLY face element needs a list property vertex_indices", file);
  endif

  if (strcmp (fmt, "ascii"))
    [vals, nread, ~, nextidx] = sscanf (char (body), "%f");
    if (nextidx <= numel (body) && ! all (isspace (char (body(nextidx:end)))))
      error ("lafortune:meshReadFormat",
             "mesh_read: %s: non-numeric data in the PLY body at byte %d",
             file, p + nextidx);
    endif
    vals = vals(:).';
    pos = 0;
    for k = 1:numel (elems)
      [cols, pos] = ply_ascii_elem (vals, pos, elems(k), file);
      data{k} = cols;
    endfor
    if (pos < numel (vals))
      error ("lafortune:meshReadCount",
             "mesh_read: %s: %d values after the last PLY element (header counts too small?)",
             file, numel (vals) - pos);
    endif
  else
    big = strcmp (fmt, "binary_big_endian");
    pos = 0;
    for k = 1:numel (elems)
      [cols, pos] = ply_binary_elem (body, pos, elems(k), big, file);
      data{k} = cols;
    endfor
    rest = body(pos+1:end);
    if (any (! ismember (rest, uint8 ([0 9 10 13 32]))))
      error ("lafortune:meshReadCount",
             "mesh_read: %s: %d bytes after the last PLY element (header counts too small?)",
             file, numel (rest));
    endif
  endif

  vd = data{iv};
  V = [vd{strcmp (vn, "x")}(:), vd{strcmp (vn, "y")}(:), vd{strcmp (vn, "z")}(:)];
  N = [];
  if (all (ismember ({"nx", "ny", "nz"}, vn)))
    N = [vd{strcmp (vn, "nx")}(:), vd{strcmp (vn, "ny")}(:), vd{strcmp (vn, "nz")}(:)];
  endif
  F = fan (data{jf}{fl}, rows (V), file);
  [V, N] = finish_vertices (V, N, file);
endfunction

function t = ply_type (s, file)
  names = {"char", "int8", "uchar", "uint8", "short", "int16", "ushort", "uint16", ...
           "int", "int32", "uint", "uint32", "float", "float32", "double", "float64"};
  types = {"int8", "int8", "uint8", "uint8", "int16", "int16", "uint16", "uint16", ...
           "int32", "int32", "uint32", "uint32", "single", "single", "double", "double"};
  i = find (strcmp (s, names), 1);
  if (isempty (i))
    error ("lafortune:meshReadFormat", "mesh_read: %s: unknown PLY type '%s'", file, s);
  endif
  t = types{i};
endfunction

function n = type_bytes (t)
  switch (t)
    case {"int8", "uint8"}
      n = 1;
    case {"int16", "uint16"}
      n = 2;
    case {"int32", "uint32", "single"}
      n = 4;
    otherwise
      n = 8;
  endswitch
endfunction

## One element of an ASCII PLY body.  COLS{p} is count x 1 (scalar property)
## or a cell of per-record rows (list property; a matrix when all records
## have the same length).
function [cols, pos] = ply_ascii_elem (vals, pos, el, file)
  np = numel (el.props);
  n = el.count;
  cols = cell (1, np);
  if (n == 0)
    return;
  endif
  islist = [el.props.list];
  ## fast path: every list has the length it has in the first record
  len = ones (1, np);
  off = 0;
  ok = true;
  for p = 1:np
    if (islist(p))
      if (pos + off + 1 > numel (vals))
        ok = false;
        break;
      endif
      len(p) = 1 + vals(pos + off + 1);
    endif
    off += len(p);
  endfor
  if (ok && all (len >= 1) && all (len == fix (len)))
    rec = sum (len);
    if (pos + rec * n > numel (vals))
      error ("lafortune:meshReadTruncated",
             "mesh_read: %s: PLY element '%s' declares %d records, the file ends before",
             file, el.name, n);
    endif
    M = reshape (vals(pos + (1:rec*n)), rec, n);
    starts = cumsum ([0 len]);
    same = true;
    for p = find (islist)
      same = same && all (M(starts(p)+1,:) == len(p) - 1);
    endfor
    if (same)
      for p = 1:np
        if (islist(p))
          cols{p} = M(starts(p)+2:starts(p+1),:).';
        else
          cols{p} = M(starts(p)+1,:).';
        endif
      endfor
      pos += rec * n;
      return;
    endif
  endif
  ## general path: lists of varying length, one record at a time
  for p = 1:np
    cols{p} = cell (n, 1);
  endfor
  for r = 1:n
    for p = 1:np
      if (pos + 1 > numel (vals))
        error ("lafortune:meshReadTruncated",
               "mesh_read: %s: PLY element '%s' declares %d records, the file ends in record %d",
               file, el.name, n, r);
      endif
      if (islist(p))
        m = vals(pos + 1);
        if (m < 0 || m != fix (m))
          error ("lafortune:meshReadFormat",
                 "mesh_read: %s: PLY element '%s' record %d: bad list length %g",
                 file, el.name, r, m);
        endif
        if (pos + 1 + m > numel (vals))
          error ("lafortune:meshReadTruncated",
                 "mesh_read: %s: PLY element '%s' declares %d records, the file ends in record %d",
                 file, el.name, n, r);
        endif
        cols{p}{r} = vals(pos + 1 + (1:m));
        pos += 1 + m;
      else
        cols{p}{r} = vals(pos + 1);
        pos += 1;
      endif
    endfor
  endfor
  for p = find (! islist)
    cols{p} = [cols{p}{:}].';
  endfor
endfunction

function x = bytes_to (b, t, big)
  ## b: nbytes x n uint8, one value per column
  if (big && rows (b) > 1)
    b = flipud (b);
  endif
  x = double (typecast (b(:), t));
endfunction

function [cols, pos] = ply_binary_elem (body, pos, el, big, file)
  np = numel (el.props);
  n = el.count;
  cols = cell (1, np);
  if (n == 0)
    return;
  endif
  islist = [el.props.list];
  sz = zeros (1, np);
  csz = zeros (1, np);
  for p = 1:np
    sz(p) = type_bytes (el.props(p).type);
    if (islist(p))
      csz(p) = type_bytes (el.props(p).ctype);
    endif
  endfor
  nb = numel (body);
  ## fast path: every list has the length it has in the first record
  len = zeros (1, np);   # bytes per property in a record
  cnt = zeros (1, np);
  off = 0;
  ok = true;
  for p = 1:np
    if (islist(p))
      if (pos + off + csz(p) > nb)
        ok = false;
        break;
      endif
      cnt(p) = bytes_to (body(pos + off + (1:csz(p))).', el.props(p).ctype, big);
      len(p) = csz(p) + cnt(p) * sz(p);
    else
      len(p) = sz(p);
    endif
    off += len(p);
  endfor
  if (ok && all (cnt >= 0))
    rec = sum (len);
    if (pos + rec * n > nb)
      error ("lafortune:meshReadTruncated",
             "mesh_read: %s: PLY element '%s' declares %d records, the file ends before",
             file, el.name, n);
    endif
    M = reshape (body(pos + (1:rec*n)), rec, n);
    starts = cumsum ([0 len]);
    same = true;
    for p = find (islist)
      c = bytes_to (M(starts(p) + (1:csz(p)),:), el.props(p).ctype, big);
      same = same && all (c == cnt(p));
    endfor
    if (same)
      for p = 1:np
        if (islist(p))
          B = M(starts(p) + csz(p) + (1:cnt(p)*sz(p)),:);
          cols{p} = reshape (bytes_to (reshape (B, sz(p), []), el.props(p).type, big),
                             cnt(p), n).';
        else
          cols{p} = bytes_to (M(starts(p) + (1:sz(p)),:), el.props(p).type, big);
        endif
      endfor
      pos += rec * n;
      return;
    endif
  endif
  ## general path: lists of varying length, one record at a time
  for p = 1:np
    cols{p} = cell (n, 1);
  endfor
  for r = 1:n
    for p = 1:np
      if (islist(p))
        if (pos + csz(p) > nb)
          error ("lafortune:meshReadTruncated",
                 "mesh_read: %s: PLY element '%s' declares %d records, the file ends in record %d",
                 file, el.name, n, r);
        endif
        m = bytes_to (body(pos + (1:csz(p))).', el.props(p).ctype, big);
        pos += csz(p);
        if (m < 0 || pos + m * sz(p) > nb)
          error ("lafortune:meshReadTruncated",
                 "mesh_read: %s: PLY element '%s' declares %d records, the file ends in record %d",
                 file, el.name, n, r);
        endif
        cols{p}{r} = bytes_to (reshape (body(pos + (1:m*sz(p))), sz(p), m),
                               el.props(p).type, big).';
        pos += m * sz(p);
      else
        if (pos + sz(p) > nb)
          error ("lafortune:meshReadTruncated",
                 "mesh_read: %s: PLY element '%s' declares %d records, the file ends in record %d",
                 file, el.name, n, r);
        endif
        cols{p}{r} = bytes_to (body(pos + (1:sz(p))).', el.props(p).type, big);
        pos += sz(p);
      endif
    endfor
  endfor
  for p = find (! islist)
    cols{p} = [cols{p}{:}].';
  endfor
endfunction

## Fan-triangulate 0-based PLY polygons (matrix: one polygon per row, or a
## cell of rows) into 1-based triangles, checking counts and ranges.
function F = fan (polys, nv, file)
  if (iscell (polys))
    lens = cellfun (@numel, polys);
  else
    lens = repmat (columns (polys), rows (polys), 1);
  endif
  if (isempty (lens))
    error ("lafortune:meshReadCount", "mesh_read: %s: the mesh has no faces", file);
  endif
  if (any (lens < 3))
    i = find (lens < 3, 1);
    error ("lafortune:meshReadCount",
           "mesh_read: %s: face %d has %d vertices, expected at least 3", file, i, lens(i));
  endif
  F = zeros (0, 3);
  key = zeros (0, 1);
  for m = unique (lens(:)).'
    if (iscell (polys))
      P = vertcat (polys{lens == m});
    else
      P = polys;
    endif
    id = find (lens(:) == m);
    k = (2:m-1);
    F = [F; repmat(P(:,1), 1, m-2)(:), P(:,k)(:), P(:,k+1)(:)];
    key = [key; (id + (k - 1) / m)(:)];    # file order: polygon, then fan
  endfor
  [~, o] = sort (key);
  F = F(o,:);
  if (any (F(:) != fix (F(:))) || any (F(:) < 0) || any (F(:) >= nv))
    bad = F(F != fix (F) | F < 0 | F >= nv);
    error ("lafortune:meshReadIndex",
           "mesh_read: %s: vertex index %g out of range (expected 0 to %d)",
           file, bad(1), nv - 1);
  endif
  F += 1;
endfunction

function [V, N] = finish_vertices (V, N, file)
  if (isempty (V))
    error ("lafortune:meshReadCount", "mesh_read: %s: the mesh has no vertices", file);
  endif
  if (! all (isfinite (V(:))))
    error ("lafortune:meshReadFormat", "mesh_read: %s: non-finite vertex coordinates", file);
  endif
  if (! isempty (N))
    len = sqrt (sum (N .^ 2, 2));
    ok = len > 0 & isfinite (len);
    N(ok,:) ./= len(ok);
    N(! ok,:) = 0;
  endif
endfunction

## ---------------------------------------------------------------- OBJ
function [V, F, N] = read_obj (txt, file)
  txt(txt == "\r" | txt == "\t") = " ";
  if (isempty (txt) || txt(end) != "\n")
    txt(end+1) = "\n";
  endif
  nl = find (txt == "\n");
  ls = [1, nl(1:end-1) + 1];                 # line starts
  ## first non-blank character of each line (or its newline)
  fs = ls;
  lead = find (txt(ls) == " ");
  if (! isempty (lead))
    nb = find (txt != " ");
    fs(lead) = nb(lookup (nb, ls(lead) - 0.5) + 1);
  endif
  c1 = txt(fs);
  c2 = txt(min (fs + 1, numel (txt)));
  c3 = txt(min (fs + 2, numel (txt)));
  isv = c1 == "v" & c2 == " ";
  isn = c1 == "v" & c2 == "n" & c3 == " ";
  isf = c1 == "f" & c2 == " ";

  V = obj_numbers (txt, fs(isv) + 1, nl(isv), 3, "v", file);
  NN = obj_numbers (txt, fs(isn) + 2, nl(isn), 3, "vn", file);
  if (isempty (V))
    error ("lafortune:meshReadCount", "mesh_read: %s: the mesh has no vertices", file);
  endif
  if (! any (isf))
    error ("lafortune:meshReadCount", "mesh_read: %s: the mesh has no faces", file);
  endif

  ## face lines: one string, corners separated by blanks, "v//n" -> "v/0/n"
  fl = find (isf);
  s = line_text (txt, fs(fl) + 1, nl(fl));
  s = strrep (s, "//", "/0/");
  if (any (! ismember (s, "0123456789-/ \n")))
    i = find (! ismember (s, "0123456789-/ \n"), 1);
    error ("lafortune:meshReadFormat",
           "mesh_read: %s: bad character '%s' in a face line", file, s(i));
  endif
  blank = s == " " | s == "\n";
  tokstart = find (! blank & [true, blank(1:end-1)]);
  tokend = find (! blank & [blank(2:end), true]);
  eol = find (s == "\n");
  line_of_tok = lookup (eol, tokstart) + 1;  # face line of each corner
  ncorner = accumarray (line_of_tok(:), 1, [numel(fl) 1]);
  if (any (ncorner < 3))
    i = find (ncorner < 3, 1);
    error ("lafortune:meshReadCount",
           "mesh_read: %s: face on line %d has %d vertices, expected at least 3",
           file, fl(i), ncorner(i));
  endif
  sl = cumsum (s == "/");
  nslash = sl(tokend) - [0, sl(1:end-1)](tokstart);
  if (any (nslash > 2) || any (s(tokend) == "/"))
    error ("lafortune:meshReadFormat", "mesh_read: %s: bad face corner", file);
  endif
  s(s == "/") = " ";
  [num, cnt] = sscanf (s, "%f");
  if (cnt != numel (tokstart) + sum (nslash))
    error ("lafortune:meshReadFormat", "mesh_read: %s: bad face corner", file);
  endif
  first = cumsum ([1, nslash(1:end-1) + 1]);   # position of each corner's v index
  vi = num(first).';
  hasn = nslash == 2;
  ni = zeros (size (vi));
  ni(hasn) = num(first(hasn) + 2);
  if (any (vi != fix (vi)) || any (ni != fix (ni)))
    error ("lafortune:meshReadFormat", "mesh_read: %s: non-integer face index", file);
  endif
  ## negative indices: relative to the vertices / normals read so far
  nvb = cumsum (isv)(fl(line_of_tok));
  nnb = cumsum (isn)(fl(line_of_tok));
  vi(vi < 0) = nvb(vi < 0) + vi(vi < 0) + 1;
  ni(ni < 0) = nnb(ni < 0) + ni(ni < 0) + 1;
  nv = rows (V);
  if (any (vi < 1 | vi > nv))
    bad = vi(vi < 1 | vi > nv);
    error ("lafortune:meshReadIndex",
           "mesh_read: %s: vertex index %d out of range (expected 1 to %d)", file, bad(1), nv);
  endif
  if (any (hasn & (ni < 1 | ni > rows (NN))))
    bad = ni(hasn & (ni < 1 | ni > rows (NN)));
    error ("lafortune:meshReadIndex",
           "mesh_read: %s: normal index %d out of range (expected 1 to %d)",
           file, bad(1), rows (NN));
  endif

  ## fan triangulation, grouped by corner count
  cstart = cumsum ([1; ncorner(1:end-1)]);
  F = zeros (0, 3);
  key = zeros (0, 1);
  for m = unique (ncorner).'
    id = find (ncorner == m);
    P = reshape (vi(cstart(id) + (0:m-1)), numel (id), m);   # polygons x m
    k = 2:m-1;
    F = [F; repmat(P(:,1), 1, m-2)(:), P(:,k)(:), P(:,k+1)(:)];
    key = [key; (id + (k - 1) / m)(:)];        # file order: polygon, then fan
  endfor
  [~, o] = sort (key);
  F = F(o,:);

  N = [];
  if (all (hasn) && ! isempty (NN))
    acc = zeros (nv, 3);
    for c = 1:3
      acc(:,c) = accumarray (vi(:), NN(ni, c), [nv 1]);
    endfor
    N = acc;
  endif
  [V, N] = finish_vertices (V, N, file);
endfunction

## The text of lines (from character A(k) to the newline E(k)), joined.
function s = line_text (txt, a, e)
  if (isempty (a))
    s = "";
    return;
  endif
  len = e - a + 1;                           # includes the newline
  idx = ones (1, sum (len));
  cs = cumsum (len);
  idx(1) = a(1);
  idx(cs(1:end-1) + 1) = a(2:end) - e(1:end-1);
  s = txt(cumsum (idx));
endfunction

## The first K numbers of each of the lines (text from A(k) to E(k)).
function X = obj_numbers (txt, a, e, K, what, file)
  if (isempty (a))
    X = zeros (0, K);
    return;
  endif
  s = line_text (txt, a, e);
  blank = s == " " | s == "\n";
  tokstart = find (! blank & [true, blank(1:end-1)]);
  eol = find (s == "\n");
  ntok = accumarray (lookup (eol, tokstart(:)) + 1, 1, [numel(a) 1]);
  if (any (ntok < K))
    i = find (ntok < K, 1);
    error ("lafortune:meshReadFormat",
           "mesh_read: %s: '%s' line %d has %d numbers, expected %d",
           file, what, i, ntok(i), K);
  endif
  [num, cnt] = sscanf (s, "%f");
  if (cnt != sum (ntok))
    error ("lafortune:meshReadFormat", "mesh_read: %s: bad number in a '%s' line", file, what);
  endif
  first = cumsum ([1; ntok(1:end-1)]);
  X = reshape (num(first + (0:K-1)), numel (first), K);
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
%! write_text (f, "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1/1 2/2 3/3\nf 1 3 4\n");
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
