## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {[@var{V}, @var{F}, @var{N}, @var{info}] =} mesh_obj (@var{bytes}, @var{file})
## Parse the bytes of a Wavefront OBJ file (private, for mesh_read; see its
## help for what is read).  @var{F} holds the fan-triangulated faces
## (1-based, range checked), @var{N} the vertex normals or [], @var{info} the
## fields format, polygons, normals and split.  A vertex that the faces use
## with different normals is split: one copy per distinct normal, the copies
## appended after the file's vertices.  Every malformed input is an error
## with an identifier lafortune:meshRead*.
## @end deftypefn
function [V, F, N, info] = mesh_obj (bytes, file)
  txt = char (bytes(:).');
  txt(txt == "\r" | txt == "\t" | txt == "\f" | txt == "\v") = " ";
  if (isempty (txt) || txt(end) != "\n")
    txt(end+1) = "\n";
  endif
  txt = strip_comments (txt);
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
  ist = c1 == "v" & c2 == "t" & c3 == " ";
  isf = c1 == "f" & c2 == " ";

  V = obj_numbers (txt, fs(isv) + 1, nl(isv), find (isv), "v", file);
  NN = obj_numbers (txt, fs(isn) + 2, nl(isn), find (isn), "vn", file);
  if (isempty (V))
    error ("lafortune:meshReadCount", "mesh_read: %s: the mesh has no vertices", file);
  endif
  if (! any (isf))
    error ("lafortune:meshReadCount", "mesh_read: %s: the mesh has no faces", file);
  endif

  ## face lines: one string, corners separated by blanks
  fl = find (isf);
  s = line_text (txt, fs(fl) + 1, nl(fl));
  i = find (! ismember (s, "0123456789-/ \n"), 1);
  if (! isempty (i))
    error ("lafortune:meshReadFormat",
           "mesh_read: %s: bad character '%s' in the face on line %d (expected v, v/vt, v//vn or v/vt/vn corners)",
           file, s(i), fl(lookup (find (s == "\n"), i) + 1));
  endif
  s = strrep (s, "//", "/0.5/");             # 0.5: no vt (never a valid index)
  blank = s == " " | s == "\n";
  tokstart = find (! blank & [true, blank(1:end-1)]);
  tokend = find (! blank & [blank(2:end), true]);
  eol = find (s == "\n");
  line_of_tok = lookup (eol, tokstart) + 1;  # face line of each corner
  ncorner = accumarray (line_of_tok(:), 1, [numel(fl) 1]);
  if (any (ncorner < 3))
    i = find (ncorner < 3, 1);
    error ("lafortune:meshReadCount",
           "mesh_read: %s: the face on line %d has %d vertices, expected at least 3",
           file, fl(i), ncorner(i));
  endif
  sl = cumsum (s == "/");
  nslash = sl(tokend) - [0, sl(1:end-1)](tokstart);
  badc = nslash > 2 | s(tokend) == "/" | s(tokstart) == "/";
  if (any (badc))
    i = line_of_tok(find (badc, 1));
    error ("lafortune:meshReadFormat",
           "mesh_read: %s: bad corner in the face on line %d (expected v, v/vt, v//vn or v/vt/vn)",
           file, fl(i));
  endif
  s(s == "/") = " ";
  [num, cnt] = sscanf (s, "%f");
  if (cnt != numel (tokstart) + sum (nslash))
    error ("lafortune:meshReadFormat",
           "mesh_read: %s: bad number in a face (expected integer indices)", file);
  endif
  first = cumsum ([1, nslash(1:end-1) + 1]);   # position of each corner's v index
  vi = num(first).';
  hast = nslash >= 1;
  ti = zeros (size (vi));
  ti(hast) = num(first(hast) + 1);
  hast(ti == 0.5) = false;
  ti(! hast) = 0;
  hasn = nslash == 2;
  ni = zeros (size (vi));
  ni(hasn) = num(first(hasn) + 2);
  if (any (vi != fix (vi)) || any (ti != fix (ti)) || any (ni != fix (ni)))
    error ("lafortune:meshReadFormat",
           "mesh_read: %s: non-integer face index; expected integers", file);
  endif
  ## negative indices: relative to the vertices / texture coordinates /
  ## normals read so far
  ln = fl(line_of_tok);
  vi = relative (vi, isv, ln);
  ti = relative (ti, ist, ln);
  ni = relative (ni, isn, ln);
  nv = rows (V);
  check_range (vi, true (size (vi)), nv, "vertex", file);
  check_range (ti, hast, nnz (ist), "texture coordinate", file);
  check_range (ni, hasn, rows (NN), "normal", file);

  info = struct ("format", "obj", "polygons", numel (fl), "normals", "none", "split", 0);
  N = [];
  if (all (hasn))
    [vi, V, N, info.split] = split_by_normal (vi, ni, V, NN);
    info.normals = "vertex";
    if (info.split > 0)
      info.normals = "corner";
    endif
  elseif (any (hasn))
    info.normals = "ignored";
  endif
  F = mesh_fan (vi, ncorner);
endfunction

## Blank everything from a '#' to the end of its line (TXT ends in a newline).
function txt = strip_comments (txt)
  h = find (txt == "#");
  if (isempty (h))
    return;
  endif
  nl = find (txt == "\n");
  [ln, i] = unique (lookup (nl, h), "first");   # lines with a '#': the first one
  a = h(i);
  e = nl(ln + 1) - 1;                            # the end of each such line
  txt(index_ranges (a, e)) = " ";
endfunction

## Negative indices I (of corners on the lines LN) counted back from the
## last of the lines flagged in ISX before the corner's line.
function i = relative (i, isx, ln)
  neg = i < 0;
  if (any (neg))
    nbefore = cumsum (isx);
    i(neg) = nbefore(ln(neg)) + i(neg) + 1;
  endif
endfunction

function check_range (i, used, n, what, file)
  bad = find (used & (i < 1 | i > n), 1);
  if (! isempty (bad))
    error ("lafortune:meshReadIndex",
           "mesh_read: %s: %s index %d out of range (expected 1 to %d, or -1 to -%d counting back)",
           file, what, i(bad), n, n);
  endif
endfunction

## Corner normals to vertex normals.  Normals that are equal after
## normalisation count as one.  A vertex used with one normal keeps its
## index; each further normal of a vertex (in the order of first use) gets a
## copy of the vertex, appended to V.
function [vi, V, N, nsplit] = split_by_normal (vi, ni, V, NN)
  len = sqrt (sum (NN .^ 2, 2));
  U = NN ./ max (len, realmin);
  [~, ~, canon] = unique (U, "rows");        # equal normals, one id
  pair = [vi(:), canon(ni(:))(:)];
  [up, firstuse, j] = unique (pair, "rows", "first");
  ## which unique pair is the first of its vertex, in the order of first use
  [~, o] = sort (firstuse);
  [~, fv] = unique (up(o,1), "first");
  keeper = false (rows (up), 1);
  keeper(o(fv)) = true;
  newidx = zeros (rows (up), 1);
  newidx(keeper) = up(keeper,1);
  extra = o(! keeper(o));                    # further normals, by first use
  nsplit = numel (extra);
  nv = rows (V);
  newidx(extra) = nv + (1:nsplit);
  ## normal of each unique pair: the first corner's file normal
  pn = NN(ni(firstuse),:);
  N = zeros (nv + nsplit, 3);
  N(newidx,:) = pn;
  V = [V; V(up(extra,1),:)];
  vi = newidx(j).';
endfunction

## The text of lines (from character A(k) to the newline E(k)), joined.
function s = line_text (txt, a, e)
  s = txt(index_ranges (a, e));
endfunction

## The first 3 numbers of each of the lines (text from A(k) to E(k), line
## numbers LNUM in the file).
function X = obj_numbers (txt, a, e, lnum, what, file)
  K = 3;
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
           "mesh_read: %s: the '%s' line %d has %d numbers, expected %d",
           file, what, lnum(i), ntok(i), K);
  endif
  [num, cnt] = sscanf (s, "%f");
  if (cnt != sum (ntok))
    i = lookup (cumsum (ntok), cnt) + 1;     # the line of the first bad token
    error ("lafortune:meshReadFormat",
           "mesh_read: %s: bad number in the '%s' line %d (expected decimal numbers)",
           file, what, lnum(min (i, end)));
  endif
  first = cumsum ([1; ntok(1:end-1)]);
  X = reshape (num(first + (0:K-1)), numel (first), K);
endfunction
