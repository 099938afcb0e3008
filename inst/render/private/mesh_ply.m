## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {[@var{V}, @var{F}, @var{N}, @var{info}] =} mesh_ply (@var{bytes}, @var{file})
## Parse the bytes of a PLY file (private, for mesh_read; see its help for
## what is read).  @var{F} holds the fan-triangulated faces (1-based, range
## checked), @var{N} the vertex normals or [], @var{info} the fields
## format, polygons and normals.  Every malformed input is an error with an
## identifier lafortune:meshRead*.
## @end deftypefn
function [V, F, N, info] = mesh_ply (bytes, file)
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
  hb = bytes(1:hend(1)-1);
  bad = find (! (hb >= 32 & hb <= 126) & ! any (hb == uint8 ([9; 10; 13]), 1), 1);
  if (! isempty (bad))
    error ("lafortune:meshReadFormat",
           "mesh_read: %s: byte %d of the PLY header is 0x%02X; expected printable ASCII text",
           file, bad, hb(bad));
  endif
  hb(hb == 13 | hb == 9) = 32;
  header = ostrsplit (char (hb), "\n");
  body = bytes(p+1:end);

  fmt = "";
  elems = struct ("name", {}, "count", {}, "props", {});
  for k = 2:numel (header)
    w = ostrsplit (header{k}, " ", true);
    if (isempty (w) || any (strcmp (w{1}, {"comment", "obj_info"})))
      continue;
    endif
    switch (w{1})
      case "format"
        if (! isempty (fmt))
          error ("lafortune:meshReadFormat",
                 "mesh_read: %s: the PLY header has two format lines; expected one", file);
        endif
        if (numel (w) != 3 || ! any (strcmp (w{2}, {"ascii", "binary_little_endian", ...
                                                    "binary_big_endian"})))
          error ("lafortune:meshReadFormat",
                 "mesh_read: %s: unknown PLY format line '%s' (expected 'format' ascii, binary_little_endian or binary_big_endian, and a version)",
                 file, header{k});
        endif
        fmt = w{2};
      case "element"
        if (numel (w) == 3)
          c = str2double (w{3});
        endif
        if (numel (w) != 3 || ! isfinite (c) || c < 0 || c != fix (c)
            || ! all (isdigit (w{3})))
          error ("lafortune:meshReadFormat",
                 "mesh_read: %s: bad PLY line '%s' (expected 'element NAME COUNT')",
                 file, header{k});
        endif
        if (any (strcmp (w{2}, {elems.name})))
          error ("lafortune:meshReadFormat",
                 "mesh_read: %s: the PLY element '%s' is declared twice; expected once",
                 file, w{2});
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
          if (any (strcmp (pr.ctype, {"single", "double"})))
            error ("lafortune:meshReadFormat",
                   "mesh_read: %s: PLY list '%s' has a count of type %s; expected an integer type",
                   file, pr.name, w{3});
          endif
        elseif (numel (w) == 3)
          pr = struct ("name", w{3}, "list", false, "ctype", "", "type", ply_type (w{2}, file));
        else
          error ("lafortune:meshReadFormat",
                 "mesh_read: %s: bad PLY line '%s' (expected 'property TYPE NAME' or 'property list TYPE TYPE NAME')",
                 file, header{k});
        endif
        if (any (strcmp (pr.name, {elems(end).props.name})))
          error ("lafortune:meshReadFormat",
                 "mesh_read: %s: PLY element '%s' has two properties '%s'; expected distinct names",
                 file, elems(end).name, pr.name);
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
  if (! all (ismember ({"x", "y", "z"}, vn)) || any ([elems(iv).props.list]))
    error ("lafortune:meshReadFormat",
           "mesh_read: %s: PLY vertex element needs the scalar properties x, y, z (no lists)",
           file);
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
  F = ply_faces (data{jf}{fl}, rows (V), file);
  info = struct ("format", ["ply " fmt], "polygons", elems(jf).count,
                 "normals", "vertex", "split", 0);
  if (isempty (N))
    info.normals = "none";
  endif
endfunction

## 0-based PLY polygons (struct: lens, one per polygon, and vals, all the
## indices in order) to 1-based triangles, with counts and ranges checked.
function F = ply_faces (polys, nv, file)
  if (isempty (polys) || isempty (polys.lens))
    error ("lafortune:meshReadCount", "mesh_read: %s: the mesh has no faces", file);
  endif
  lens = polys.lens;
  idx = polys.vals(:);
  if (any (lens < 3))
    i = find (lens < 3, 1);
    error ("lafortune:meshReadCount",
           "mesh_read: %s: face %d has %d vertices, expected at least 3", file, i, lens(i));
  endif
  bad = find (idx != fix (idx) | idx < 0 | idx >= nv, 1);
  if (! isempty (bad))
    error ("lafortune:meshReadIndex",
           "mesh_read: %s: vertex index %g out of range (expected 0 to %d)",
           file, idx(bad), nv - 1);
  endif
  F = mesh_fan (idx + 1, lens);
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
## or a struct with fields lens (count x 1) and vals (all the items, record
## after record) (list property).
function [cols, pos] = ply_ascii_elem (vals, pos, el, file)
  np = numel (el.props);
  n = el.count;
  cols = cell (1, np);
  if (n == 0 || np == 0)
    return;
  endif
  if (n * np > numel (vals) - pos)           # each record has >= np values
    error ("lafortune:meshReadTruncated",
           "mesh_read: %s: PLY element '%s' declares %d records, the file ends before",
           file, el.name, n);
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
  ## (lists of other lengths further on: the general path below)
  if (ok && all (len >= 1) && all (len == fix (len)) && pos + sum (len) * n <= numel (vals))
    rec = sum (len);
    M = reshape (vals(pos + (1:rec*n)), rec, n);
    starts = cumsum ([0 len]);
    same = true;
    for p = find (islist)
      same = same && all (M(starts(p)+1,:) == len(p) - 1);
    endfor
    if (same)
      for p = 1:np
        if (islist(p))
          cols{p} = struct ("lens", repmat (len(p) - 1, n, 1),
                            "vals", reshape (M(starts(p)+2:starts(p+1),:), [], 1));
        else
          cols{p} = M(starts(p)+1,:).';
        endif
      endfor
      pos += rec * n;
      return;
    endif
  endif
  ## general path: lists of varying length
  cw = double (islist);                      # values of a list's count
  [off, cnt, pos] = ply_walk (repmat ({vals(pos+1:end)}, 1, np), n, islist, cw,
                              ones (1, np), pos, numel (vals), el, file);
  for p = 1:np
    if (islist(p))
      k = cnt(:,p) > 0;
      cols{p} = struct ("lens", cnt(:,p),
                        "vals", vals(index_ranges (off(k,p) + 2, off(k,p) + 1 + cnt(k,p))).');
    else
      cols{p} = vals(off(:,p) + 1).';
    endif
  endfor
endfunction

## Where each record's properties start, records of varying length: OFF
## (n x np, 0-based offsets in units: values or bytes), the list lengths CNT
## (n x np) and the offset Q after the element.  COUNTAT{p} holds for a
## list p the count that would start at each unit from the element's start
## Q; CW and IW are the units of a count and of an item (or scalar); TOTAL
## the units in the data.  One pass in record order, with every count and
## the end of the data checked.
function [off, cnt, q] = ply_walk (countat, n, islist, cw, iw, q, total, el, file)
  np = numel (islist);
  q0 = q;
  need = iw;                                 # units a property needs to start
  need(islist) = cw(islist);
  bad = cell (1, np);
  for p = find (islist)                      # a bad count ends the walk (q = Inf)
    c = double (countat{p});
    bad{p} = ! (c >= 0 & c == fix (c));
    c(bad{p}) = Inf;
    countat{p} = c;
  endfor
  off = NaN (n, np);
  stop = 0;                                  # the record the walk stopped in
  if (np == 1)                               # the usual face element: the list alone
    c = countat{1};
    for r = 1:n
      if (q + need > total)
        stop = r;
        break;
      endif
      off(r) = q;
      q += cw + c(q - q0 + 1) * iw;
    endfor
  else
    for r = 1:n
      for p = 1:np
        if (q + need(p) > total)
          stop = r;
          break;
        endif
        off(r,p) = q;
        if (islist(p))
          q += cw(p) + countat{p}(q - q0 + 1) * iw(p);
        else
          q += iw(p);
        endif
      endfor
      if (stop)
        break;
      endif
    endfor
  endif
  if (! stop && q > total)
    stop = n;
  endif
  cnt = zeros (n, np);
  for p = find (islist)
    k = ! isnan (off(:,p));
    cnt(k,p) = countat{p}(off(k,p) - q0 + 1);
    i = find (bad{p}(off(k,p) - q0 + 1), 1);
    if (! isempty (i))                       # a bad count stopped the walk
      error ("lafortune:meshReadFormat",
             "mesh_read: %s: PLY element '%s' record %d: bad list length (expected an integer >= 0)",
             file, el.name, i);
    endif
  endfor
  if (stop)
    ply_truncated (el, stop, file);
  endif
endfunction

function ply_truncated (el, r, file)
  error ("lafortune:meshReadTruncated",
         "mesh_read: %s: PLY element '%s' declares %d records, the file ends in record %d",
         file, el.name, el.count, r);
endfunction

function x = bytes_to (b, t, big)
  ## b: nbytes x n uint8, one value per column
  if (big && rows (b) > 1)
    b = flipud (b);
  endif
  x = double (typecast (b(:), t));
endfunction

## One element of a binary PLY body, COLS as for ply_ascii_elem.
function [cols, pos] = ply_binary_elem (body, pos, el, big, file)
  np = numel (el.props);
  n = el.count;
  cols = cell (1, np);
  if (n == 0 || np == 0)
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
  if (n * (sum (csz(islist)) + sum (sz(! islist))) > nb - pos)   # the smallest records
    error ("lafortune:meshReadTruncated",
           "mesh_read: %s: PLY element '%s' declares %d records, the file ends before",
           file, el.name, n);
  endif
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
  ## (lists of other lengths further on: the general path below)
  if (ok && all (cnt >= 0) && pos + sum (len) * n <= nb)
    rec = sum (len);
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
          cols{p} = struct ("lens", repmat (cnt(p), n, 1),
                            "vals", bytes_to (reshape (B, sz(p), []), el.props(p).type, big));
        else
          cols{p} = bytes_to (M(starts(p) + (1:sz(p)),:), el.props(p).type, big);
        endif
      endfor
      pos += rec * n;
      return;
    endif
  endif
  ## general path: lists of varying length
  countat = cell (1, np);
  for p = find (islist)
    countat{p} = count_at (body(pos+1:end), el.props(p).ctype, csz(p), big);
  endfor
  [off, cnt, pos] = ply_walk (countat, n, islist, csz, sz, pos, nb, el, file);
  for p = 1:np
    t = el.props(p).type;
    if (islist(p))
      k = cnt(:,p) > 0;
      B = body(index_ranges (off(k,p) + csz(p) + 1, off(k,p) + csz(p) + cnt(k,p) * sz(p)));
      cols{p} = struct ("lens", cnt(:,p), "vals", bytes_to (reshape (B, sz(p), []), t, big));
    else
      cols{p} = bytes_to (reshape (body(off(:,p).' + (1:sz(p)).'), sz(p), n), t, big);
    endif
  endfor
endfunction

## The count of type T (CSZ bytes) that would start at each byte of BODY
## (the bytes themselves for a 1-byte type).
function c = count_at (body, t, csz, big)
  nb = numel (body);
  if (csz == 1)
    c = typecast (body(:), t);               # 1 byte each
    return;
  endif
  c = zeros (nb, 1);
  for o = 0:csz-1
    k = floor ((nb - o) / csz);
    if (k > 0)
      c(o + 1 + csz * (0:k-1)) = bytes_to (reshape (body(o + (1:k*csz)), csz, k), t, big);
    endif
  endfor
endfunction
