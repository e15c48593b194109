"""Two loss terms written in Python with torch, to register under a name of your choice:

    import ppsynth, python_terms
    ppsynth.register_loss("py_gram", python_terms.gram_loss, defaults={"weight": 0.08})
    ppsynth.register_point_term("repulsion", python_terms.repulsion, defaults={"h": 0.03})

The test suite (python/tests/test_terms.py) and docs/lab/performance/bench_python_terms.py use them.
"""
import torch


def gram_loss(output, target, params):
    """The paper's Gram loss (§3.1): sum over the layers of the squared difference of the
    Gram matrices F F^T / (C H W) of output and exemplar features."""
    def gram(f):
        m = f.reshape(f.shape[1], -1)
        return m @ m.t() / f.numel()
    return sum((gram(o) - gram(t)).pow(2).sum() for o, t in zip(output, target))


def repulsion(moving, frozen, params, stage):
    """Gaussian repulsion of width params["h"] between the moving points, and from the frozen
    ones, per moving point."""
    h2 = params["h"] ** 2
    n = moving.shape[0]
    v = torch.exp(-(moving[:, None, :] - moving[None, :, :]).pow(2).sum(-1) / h2).triu(1).sum() / n
    if frozen.shape[0]:
        v = v + torch.exp(-(moving[:, None, :] - frozen[None, :, :]).pow(2).sum(-1) / h2).sum() / n
    return v
