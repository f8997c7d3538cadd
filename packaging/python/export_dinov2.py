#!/usr/bin/env python3
"""Export DINOv2 ViT-L/14 with registers (dinov2_vitl14_reg) to TorchScript for SAGrid.

SAGrid's `dinov2` feature backend (sagrid extract --backend dinov2 --dinov2-model FILE) runs the
model from C++ with this contract, which is what TRELLIS's dataset_toolkits/extract_feature.py uses:

    forward(x: float32 [B, 3, 518, 518])  ->  float32 [B, 1369, 1024]

x is the RGB render on a black background, normalized with ImageNet mean/std (SAGrid does that);
the output is the *pre-norm* patch tokens (features["x_prenorm"]) without the CLS and the 4
register tokens, 37 x 37 patches in row-major order.

Run it where the weights are (needs torch and network access or a torch.hub cache):

    python3 export_dinov2.py --out dinov2_vitl14_reg.pt
    # offline, from a local clone of facebookresearch/dinov2 with the weights in the hub cache:
    python3 export_dinov2.py --repo /path/to/dinov2 --source local --out dinov2_vitl14_reg.pt

Then: sagrid extract MESH --backend dinov2 --dinov2-model dinov2_vitl14_reg.pt --out OUT
Not run by SAGrid's build or tests (no weights there); the C++ side is tested with stand-in
models of the same contract (tests/core/features_torch/).
"""
import argparse

import torch


class PrenormPatchTokens(torch.nn.Module):
    """Wraps a DINOv2 model so forward returns only the pre-norm patch tokens."""

    def __init__(self, model):
        super().__init__()
        self.model = model
        self.skip = 1 + model.num_register_tokens  # CLS + registers come first

    def forward(self, x):
        tokens = self.model.forward_features(x)["x_prenorm"]
        return tokens[:, self.skip:, :]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", required=True, help="TorchScript file to write")
    parser.add_argument("--repo", default="facebookresearch/dinov2", help="torch.hub repo or local clone")
    parser.add_argument("--source", default="github", choices=["github", "local"])
    parser.add_argument("--model", default="dinov2_vitl14_reg")
    args = parser.parse_args()

    model = torch.hub.load(args.repo, args.model, source=args.source).eval()
    wrapped = PrenormPatchTokens(model).eval()
    example = torch.zeros(1, 3, 518, 518)
    with torch.no_grad():
        traced = torch.jit.trace(wrapped, example, check_trace=False)
        out = traced(example)
    expected = (1, 37 * 37, 1024)
    if tuple(out.shape) != expected:
        raise SystemExit(f"unexpected output shape {tuple(out.shape)}, expected {expected}")
    traced.save(args.out)
    print(f"wrote {args.out}: [B, 3, 518, 518] -> [B, 1369, 1024] pre-norm patch tokens")


if __name__ == "__main__":
    main()
