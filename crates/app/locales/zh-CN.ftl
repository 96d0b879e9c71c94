
### paper

paper-unavailable = 此图对应的演示不可用
paper-figure = 图 { $number }
paper-section = 第 { $number } 节
paper-section-figure = 第 { $section } 节，图 { $figure }
paper-near-agrees = 演示计算得 { $computed }，在舍入范围内与论文的 { $claimed } 相符（容差 ±{ $tolerance }）。
paper-near-differs = 演示计算得 { $computed }，与论文的 { $claimed } 不符（容差 ±{ $tolerance }）。
paper-below-agrees = 演示计算得 { $computed }，低于论文给出的上限 { $bound }。
paper-below-differs = 演示计算得 { $computed }，高于论文给出的上限 { $bound }。
paper-range = { $low } 至 { $high }
paper-range-agrees = 演示计算得 { $low } 至 { $high }，与论文所述一致。
paper-range-differs = 演示计算得 { $low } 至 { $high }，与论文给出的范围不符。
paper-peak = 通过搜索得到的 |H(r)| 最大值位于 r = { $found }，而公式给出的是 { $formula }。
paper-slope = 在论文的步长 h = { $step } 及其五次减半（直至 { $smallest }）上，拟合斜率为 { $slope }。
paper-reason-context = { $verdict }{ $context }
paper-exhibit-fig1a = 四分之一车辆模型（m = 300 kg，k = 24 kN/m，x₀ = 60 mm）在舒适、性能、临界阻尼和过阻尼设置下的自由响应。
paper-exhibit-fig1b = 调节时间随阻尼比的变化及其最小值。
paper-exhibit-fig2a = 串联 RLC 回路（L = 0.5 H，C = 20 mF，V₀ = 12 V）中电阻跨越各阻尼状态时的电流。
paper-exhibit-fig2b = 同一回路的电容电压。
paper-exhibit-fig3a = 一组阻尼比下频率响应的幅值。
paper-exhibit-fig3b = 频率响应的相位。
paper-exhibit-fig4a = 轻阻尼振子（ζ = 0.05，ωₙ = 2 rad/s）在 h = 0.3 s 时欧拉法和 RK4 与精确响应的对比。
paper-exhibit-fig4b = 双对数坐标下最大误差随步长的变化及其斜率。
paper-exhibit-fig5 = 一个方程，多种机器：满足同一方程 a·y'' + b·y' + c·y = f(t) 的机械、电气及其他系统。
paper-exhibit-table1 = 机电类比：质量 ↔ 电感，阻尼器 ↔ 电阻，弹簧 ↔ 1/电容。
paper-exhibit-table2 = 各种阻尼状态：条件、根、行为与实例。
paper-exhibit-table3 = 积分方法比较：同一步长下的误差、阶数与稳定性。
paper-claim-fig1-zeta-optimum = 阻尼比约为 0.7 时调节时间最短（5 % 误差带）。
paper-claim-sec3-natural-frequency = 四分之一车辆模型的固有频率约为 8.9 rad/s（约 1.4 Hz）。
paper-claim-sec4-critical-resistance = 当 R = 2√(L/C) = 10 Ω 时回路处于临界阻尼。
paper-claim-fig3-q-factor = ζ = 0.05 时 Q = 10。
paper-claim-fig3-q-factor-light = ζ = 0.01 时 Q = 50。
paper-claim-sec5-peak-frequency = 响应在 ω = ωₙ√(1 − 2ζ²) 处达到峰值，略低于 ωₙ（在 ζ = 0.1 时核对）。
paper-claim-fig4-euler-error = h = 0.3 s 时欧拉法的最大误差约为 0.08。
paper-claim-fig4-rk4-error = h = 0.3 s 时 RK4 的最大误差小于 0.001。
paper-claim-fig4-euler-slope = 在双对数图上，欧拉法的误差以斜率 ≈ 1 下降。
paper-claim-sec7-mass-tolerance = 簧上质量 ±10 % 的不确定性使 ζ = 1.0 变为 0.91 至 1.10 之间的值。
paper-claim-fig1-zeta-optimum-context = 若取 2 % 误差带，调节最快的 ζ 则为 { $value }。
paper-claim-sec3-natural-frequency-context = 以赫兹计：fₙ = { $value }。
paper-claim-fig4-euler-error-context = 欧拉法在此步长下不稳定：每步 |1 + hλ| = { $value }，因此其误差无界增长。
paper-claim-fig4-rk4-error-context = RK4 在此步长下稳定（每步 |R(hλ)| = { $value }），但在整个时间窗口内其误差仍超过该上限。
paper-claim-fig4-euler-slope-context = 在误差处于渐近区的小步长上拟合得到的阶数为 { $value }。
paper-claim-sec7-mass-tolerance-context = ζ = c/(2√(km)) 与 1/√m 成正比，因此质量变化 ±10 % 只使其改变约 ±5 %（质量增加 10 % 时 ωₙ 降至 { $value }）。
paper-title = 论文逐项核对
paper-summary = Zeta Lab 源自一篇关于机械与电气系统中二阶微分方程的论文（Ihenacho、Samuel、Okechukwu 等，Science Publishing Group，2026）。这里列出论文中的每一幅图和每一张表，均由复现它的演示实时绘制；论文给出的每一个数值都经过核对：每条论断都显示论文的数值、本应用计算的数值和结论。点击链接即可在完全相同的状态下打开该演示。
paper-readout-claims = 已核对的论断
paper-readout-confirmed = 已证实的论断
paper-readout-differs = 有出入的论断
paper-plot-fig1a = 图 1(a)
paper-plot-fig1b = 图 1(b)
paper-plot-fig2a = 图 2(a)
paper-plot-fig2b = 图 2(b)
paper-plot-fig3a = 图 3(a)
paper-plot-fig3b = 图 3(b)
paper-plot-fig4a = 图 4(a)
paper-plot-fig4b = 图 4(b)
paper-plot-fig5 = 图 5
paper-plot-table1 = 表 1
paper-plot-table2 = 表 2
paper-plot-table3 = 表 3
