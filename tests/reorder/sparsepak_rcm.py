"""Reference reverse Cuthill-McKee: an independent Python transcription of the logic of SPARSEPAK's GENRCM,
FNROOT, ROOTLS, RCM and DEGREE (A. George and J. W. H. Liu, "Computer Solution of Large Sparse Positive Definite
Systems", Prentice-Hall 1981, ch. 4 and its appendix), written from the routines' descriptions with the Fortran's
1-based arrays kept (index 0 unused) so that every loop bound reads as in the book. Used by the tests only.

The graph is (xadj, adjncy) as in SPARSEPAK: 1-based, the neighbours of node i are adjncy[xadj[i]:xadj[i+1]],
no self loops. read_mtx_graph builds it from a Matrix Market file with each adjacency list sorted by node number
(so the stable sort by degree in RCM breaks ties by node number)."""
import numpy as np


def read_mtx_graph(path):
    """(n, xadj, adjncy) of the symmetric pattern of a Matrix Market coordinate file, 1-based, diagonal dropped,
    duplicates merged, neighbours sorted by node number."""
    with open(path) as f:
        header = f.readline().split()
        assert header[0] == "%%MatrixMarket" and header[2] == "coordinate", path
        line = f.readline()
        while line.startswith("%"):
            line = f.readline()
        nrow, ncol, nnz = (int(t) for t in line.split())
        assert nrow == ncol, path
        nbrs = [set() for _ in range(nrow + 1)]
        for _ in range(nnz):
            t = f.readline().split()
            i, j = int(t[0]), int(t[1])
            if i != j:
                nbrs[i].add(j)
                nbrs[j].add(i)
    xadj = np.zeros(nrow + 2, dtype=np.int64)
    adjncy = [0]
    xadj[1] = 1
    for i in range(1, nrow + 1):
        adjncy.extend(sorted(nbrs[i]))
        xadj[i + 1] = xadj[i] + len(nbrs[i])
    return nrow, xadj, np.array(adjncy, dtype=np.int64)


def rootls(root, xadj, adjncy, mask, xls, ls):
    """ROOTLS: level structure rooted at root over the nodes with mask != 0, levels in discovery order.
    Fills xls[1..nlvl+1], ls[1..ccsize]; returns nlvl. The mask is restored on return."""
    mask[root] = 0
    ls[1] = root
    nlvl = 0
    lvlend = 0
    ccsize = 1
    while True:
        lbegin = lvlend + 1
        lvlend = ccsize
        nlvl += 1
        xls[nlvl] = lbegin
        for i in range(lbegin, lvlend + 1):
            node = ls[i]
            for j in range(xadj[node], xadj[node + 1]):
                nbr = adjncy[j]
                if mask[nbr] != 0:
                    ccsize += 1
                    ls[ccsize] = nbr
                    mask[nbr] = 0
        if ccsize - lvlend <= 0:
            break
    xls[nlvl + 1] = lvlend + 1
    for i in range(1, ccsize + 1):
        mask[ls[i]] = 1
    return nlvl


def fnroot(root, xadj, adjncy, mask, xls, ls):
    """FNROOT: pseudo-peripheral node of root's masked component (modified Gibbs-Poole-Stockmeyer). From the
    last level take the first node of minimum masked degree; if its level structure is deeper, repeat from it.
    Returns the last node whose level structure was built (the candidate even when it is not deeper)."""
    nlvl = rootls(root, xadj, adjncy, mask, xls, ls)
    ccsize = xls[nlvl + 1] - 1
    if nlvl == 1 or nlvl == ccsize:
        return root
    while True:
        jstrt = xls[nlvl]
        mindeg = ccsize
        root = ls[jstrt]
        if ccsize != jstrt:
            for j in range(jstrt, ccsize + 1):
                node = ls[j]
                ndeg = 0
                for k in range(xadj[node], xadj[node + 1]):
                    if mask[adjncy[k]] > 0:
                        ndeg += 1
                if ndeg < mindeg:
                    root = node
                    mindeg = ndeg
        nunlvl = rootls(root, xadj, adjncy, mask, xls, ls)
        if nunlvl <= nlvl:
            return root
        nlvl = nunlvl
        if nlvl >= ccsize:
            return root


def degree(root, xadj, adjncy, mask, deg, ls):
    """DEGREE: masked degrees of the nodes of root's component into deg; returns the component size."""
    seen = {root}
    ls[1] = root
    lvlend = 0
    ccsize = 1
    while True:
        lbegin = lvlend + 1
        lvlend = ccsize
        for i in range(lbegin, lvlend + 1):
            node = ls[i]
            ideg = 0
            for j in range(xadj[node], xadj[node + 1]):
                nbr = adjncy[j]
                if mask[nbr] == 0:
                    continue
                ideg += 1
                if nbr not in seen:
                    seen.add(nbr)
                    ccsize += 1
                    ls[ccsize] = nbr
            deg[node] = ideg
        if ccsize - lvlend <= 0:
            return ccsize


def rcm(root, xadj, adjncy, mask, perm, deg, reverse=True):
    """RCM: numbers root's masked component into perm[1..ccsize] (a view starting at the component's first
    position): breadth first from root, the unnumbered neighbours of each node appended in adjacency order and
    then linear-insertion sorted by increasing degree (stable), the whole component reversed at the end
    (reverse=False keeps the Cuthill-McKee order). Sets mask to 0 on the numbered nodes; returns ccsize."""
    ccsize = degree(root, xadj, adjncy, mask, deg, perm)
    mask[root] = 0
    if ccsize <= 1:
        return ccsize
    lvlend = 0
    lnbr = 1
    while True:
        lbegin = lvlend + 1
        lvlend = lnbr
        for i in range(lbegin, lvlend + 1):
            node = perm[i]
            fnbr = lnbr + 1
            for j in range(xadj[node], xadj[node + 1]):
                nbr = adjncy[j]
                if mask[nbr] == 0:
                    continue
                lnbr += 1
                mask[nbr] = 0
                perm[lnbr] = nbr
            if fnbr >= lnbr:
                continue
            for k in range(fnbr + 1, lnbr + 1):  # linear insertion, stops at an equal degree
                nbr = perm[k]
                l = k - 1
                while l >= fnbr and deg[perm[l]] > deg[nbr]:
                    perm[l + 1] = perm[l]
                    l -= 1
                perm[l + 1] = nbr
        if lnbr <= lvlend:
            break
    if reverse:
        perm[1 : ccsize + 1] = perm[1 : ccsize + 1][::-1].copy()
    return ccsize


def genrcm(n, xadj, adjncy, reverse=True):
    """GENRCM: for i = 1..n, each not yet numbered node starts its component: FNROOT from i, then RCM from the
    root found, numbered after the earlier components. Returns perm (0-based, perm[new] = old)."""
    mask = np.ones(n + 2, dtype=np.int64)
    perm = np.zeros(n + 2, dtype=np.int64)
    xls = np.zeros(n + 2, dtype=np.int64)
    deg = np.zeros(n + 2, dtype=np.int64)
    ls = np.zeros(n + 2, dtype=np.int64)
    num = 1
    for i in range(1, n + 1):
        if mask[i] == 0:
            continue
        root = fnroot(i, xadj, adjncy, mask, xls, ls)
        # perm[num - 1:] seen 1-based: its element 1 is perm[num].
        ccsize = rcm(root, xadj, adjncy, mask, perm[num - 1 :], deg, reverse)
        num += ccsize
        if num > n:
            break
    return perm[1 : n + 1] - 1


def bandwidth_profile(xadj, adjncy, perm):
    """Bandwidth max |i - j| and profile sum_i (i - f_i) (f_i: first column of row i of the lower triangle,
    diagonal excluded) of the graph's matrix under perm (0-based, perm[new] = old)."""
    n = len(perm)
    inv = np.empty(n, dtype=np.int64)
    inv[perm] = np.arange(n)
    bw = prof = 0
    for v in range(1, n + 1):
        i = inv[v - 1]
        nb = inv[adjncy[xadj[v] : xadj[v + 1]] - 1]
        first = min(i, int(nb.min())) if len(nb) else i
        bw = max(bw, i - first, int(nb.max()) - i if len(nb) else 0)
        prof += i - first
    return bw, prof
