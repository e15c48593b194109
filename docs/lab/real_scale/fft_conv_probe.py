#!/usr/bin/python3
"""fft_conv_probe.py [THREADS] [TILE] [CHANNELS]

Is a tiled FFT convolution faster than oneDNN's direct one for the network's widest layer
(7 x 7, CHANNELS -> CHANNELS, one 450 x 699 image: amacrine's finest grid)? Overlap-save over
TILE x TILE output tiles: each input tile's rfft2, a complex channel mix per frequency bin
(one batched matmul over bins), irfft2, the valid part kept. Prints both times and their
largest difference. Debian's python3-torch (the same LibTorch 1.13 and OpenBLAS as ppsynth).
A whole-image FFT is not tried: its weight spectrum (CHANNELS^2 x bins) is gigabytes for one
image, so its channel mix is memory-bound."""
import torch, time, sys
torch.set_num_threads(int(sys.argv[1]) if len(sys.argv) > 1 else 1)
torch.manual_seed(0)
H, W, K = 450, 699, 7
C = int(sys.argv[3]) if len(sys.argv) > 3 else 64
T = int(sys.argv[2]) if len(sys.argv) > 2 else 32   # output tile side
x = torch.randn(1, C, H, W)
w = torch.randn(C, C, K, K) * 0.05
p = K // 2
def direct(x):
    return torch.nn.functional.conv2d(x, w, padding=p)
L = T + K - 1                      # input tile side (valid conv of an L tile gives T outputs)
F = L                               # fft size: circular conv of size L, valid part T x T is exact
ny, nx = -(-H // T), -(-W // T)
wf = torch.fft.rfft2(torch.flip(w, [2, 3]), s=(F, F))              # Co Ci F F/2+1
wmat = wf.permute(2, 3, 1, 0).reshape(-1, C, C).contiguous()       # bins x Ci x Co
def tiled(x):
    xp = torch.nn.functional.pad(x, (p, p + nx * T - W, p, p + ny * T - H))   # 1 C (ny T + K-1) (nx T + K-1)
    tiles = xp.unfold(2, L, T).unfold(3, L, T)                      # 1 C ny nx L L
    tiles = tiles[0].permute(1, 2, 0, 3, 4).reshape(ny * nx, C, L, L)
    xf = torch.fft.rfft2(tiles, s=(F, F))                           # n C F F/2+1
    bins = xf.shape[2] * xf.shape[3]
    a = xf.permute(2, 3, 0, 1).reshape(bins, ny * nx, C)
    yf = torch.bmm(a, wmat)                                          # bins x n x Co
    yf = yf.reshape(F, F // 2 + 1, ny * nx, C).permute(2, 3, 0, 1)
    y = torch.fft.irfft2(yf, s=(F, F))                               # n Co F F
    y = y[:, :, K - 1:K - 1 + T, K - 1:K - 1 + T]                   # the valid part
    y = y.reshape(ny, nx, C, T, T).permute(2, 0, 3, 1, 4).reshape(1, C, ny * T, nx * T)
    return y[:, :, :H, :W]
for r in range(2):
    t = time.time(); yd = direct(x); td = time.time() - t
    t = time.time(); yt = tiled(x); tt = time.time() - t
print('threads %d tile %d: direct %.3f s, tiled fft %.3f s (%.2fx); max abs diff %.2e of %.1f' % (torch.get_num_threads(), T, td, tt, td / tt, (yd - yt).abs().max().item(), yd.abs().max().item()))
