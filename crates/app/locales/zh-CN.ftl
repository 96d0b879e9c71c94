
### resonance

resonance-axis-ratio = 频率比 r = ω/ωₙ
resonance-axis-amplification = 放大系数 |H| = X/(F₀/k)
resonance-axis-magnitude-db = 幅值 20·log₁₀|H|
resonance-axis-phase = 相位 ∠H（x 滞后于 F）
resonance-plot-magnitude-db = 放大系数 |H(r)|（dB）
resonance-family = 曲线族 ζ = { $from } … { $to }
resonance-current = 当前 ζ = { $zeta }
resonance-drive = 驱动 r = { $ratio }
resonance-peak = 峰值
resonance-quadrature = r = 1 处 −90°
resonance-legend-width = 半功率宽度 r₂ − r₁ = { $width }
resonance-legend-broad = |H| ≥ |H|max/√2，直到 r = { $upper }
resonance-legend-cutoff = −3 dB 截止 r = { $upper }
resonance-band-width = 半功率点（|H| = |H|max/√2）位于 r = { $lower } 和 { $upper }：峰宽 r₂ − r₁ = { $width }
resonance-band-broad = 从 r = 0 到 r = { $upper }，|H| 始终高于 |H|max/√2：该峰没有下半功率点，因此其半功率宽度无定义
resonance-band-cutoff = |H| 在截止频率比 r = { $upper } 处降至静态值的 1/√2（−3 dB）；没有峰，也就没有半功率宽度
resonance-peak-at = 共振峰 { $gain }，位于 r = { $ratio }
resonance-no-peak = 没有共振峰（ζ ≥ 1/√2）：|H| 从 r = 0 处的 1 单调下降
resonance-describe-magnitude = { $view ->
        [db] ζ = { $zeta } 时的幅值（dB）：{ $peak }；{ $band }。在驱动频率比 r = { $drive } 处，放大系数为 { $gain }。
       *[linear] ζ = { $zeta } 时的幅值：{ $peak }；{ $band }。在驱动频率比 r = { $drive } 处，放大系数为 { $gain }。
    }
resonance-describe-phase = ζ = { $zeta } 时位移相对于力的相位滞后：低频时为 0°，对任何阻尼比在 r = 1 处均为 −90°，共振以上趋于 −180°；ζ 越小，转变越陡。在驱动频率比 r = { $drive } 处，滞后为 { $degrees }（{ $radians } rad）。
resonance-envelope = 包络线 ±E(t)
resonance-steady-amplitude = 稳态振幅 ±X
resonance-describe-time-growing = 从静止开始以 r = { $ratio }（ω = { $omega }）驱动 { $span }：没有稳态；振幅不断增大，达到 { $largest }。
resonance-describe-time = { $case ->
        [beats] 从静止开始以 r = { $ratio }（ω = { $omega }）驱动 { $span }：自由运动与受迫运动形成拍，拍周期为 { $period }（衰减时间常数 { $tau }），趋向稳态振幅 { $amplitude }，相位滞后于力 { $lag }。图中最大偏移为 { $largest }。
        [build-up] 从静止开始以 r = { $ratio }（ω = { $omega }）驱动 { $span }：在共振处振幅以时间常数 1/(ζωₙ) = { $tau } 逐渐增大，趋向稳态振幅 { $amplitude }，相位滞后于力 { $lag }。图中最大偏移为 { $largest }。
       *[transient] 从静止开始以 r = { $ratio }（ω = { $omega }）驱动 { $span }：经过瞬态过程（时间常数 { $tau }）后稳定在稳态振幅 { $amplitude }，相位滞后于力 { $lag }。图中最大偏移为 { $largest }。
    }
resonance-fixed-base = 固定基座
resonance-schematic = 固定基座上由弹簧和阻尼器支承的质量块，受力 F(t) = { $force } 推动（质量块上方的箭头），t = { $time }：偏离静止位置 { $displacement }。
resonance-beats-visible = 可见
resonance-beats-no-free-oscillation = 无（没有自由振荡，ζ ≥ 1）
resonance-beats-no-drive = 无（恒定力）
resonance-beats-same-frequency = 无（以 ω_d 驱动）
resonance-beats-too-fast = 无（与振荡一样快）
resonance-beats-dies-out = 无（自由运动先衰减消失）
resonance-title = 受迫共振
resonance-summary = 一个 1 kg 的质量块连接弹簧（k = ωₙ²·m）和阻尼器（c = 2ζωₙ·m），从静止开始，自 t = 0 起受力 F(t) = F₀·cos(ωt) 驱动。稳态时它以驱动频率运动，振幅为 |H(r)|·F₀/k，滞后于力的相角等于 H 的相位，其中 r = ω/ωₙ。轻阻尼在 r = 1 附近产生又高又窄的峰（高度 ≈ Q = 1/(2ζ)）。其半功率宽度，即 |H| = |H|max/√2 的两个频率比之间的 r₂ − r₁，在轻阻尼时 ≈ 2ζ；ζ ≈ 0.383 以上，下半功率点到达 r = 0，宽度无定义；ζ = 1/√2 以上则完全没有峰。恰好在共振处驱动时，振幅在几个时间常数 1/(ζωₙ) 内逐渐增大，不出现拍；在共振附近驱动时，自由运动与受迫运动相互形成拍，直到自由部分衰减消失。
resonance-param-zeta = 阻尼比
resonance-param-r = 激励频率比 ω/ωₙ
resonance-param-wn = 固有频率
resonance-param-F0 = 力幅值
resonance-param-view = 幅值显示方式
resonance-param-view-linear = 线性 |H|
resonance-param-view-db = 分贝 20·log₁₀|H|
resonance-readout-peak-gain = 共振峰 |H|max
resonance-readout-peak-ratio = 峰值位置 r = ω/ωₙ
resonance-readout-Q = 品质因数 Q = 1/(2ζ)
resonance-readout-peak-width = |H| 峰的半功率宽度 r₂ − r₁（ζ < 0.383）
resonance-readout-gain-at-r = 驱动处的增益 |H(r)|
resonance-readout-phase-at-r = 驱动处的相位 ∠H(r)
resonance-readout-amplitude = 稳态振幅 X = |H|·F₀/k
resonance-readout-beat-period = 拍周期 2π/|ω − ω_d|（出现拍时）
resonance-readout-beats = x(t) 中的拍
resonance-plot-magnitude = 放大系数 |H(r)|
resonance-plot-phase = 相位 ∠H(r)
resonance-plot-time = 从静止开始的响应 x(t)
resonance-preset-1 = 共振处，ζ = 0.05
resonance-preset-2 = 共振附近的拍，r = 0.9
resonance-preset-3 = 无峰，ζ ≈ 1/√2
resonance-preset-4 = 准静态，r = 0.2
resonance-preset-5 = 隔振，r = 3
