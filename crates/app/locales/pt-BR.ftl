
### resonance

resonance-axis-ratio = razão de frequências r = ω/ωₙ
resonance-axis-amplification = amplificação |H| = X/(F₀/k)
resonance-axis-magnitude-db = magnitude 20·log₁₀|H|
resonance-axis-phase = fase ∠H (atraso de x em relação a F)
resonance-plot-magnitude-db = Amplificação |H(r)| em dB
resonance-family = família ζ = { $from } … { $to }
resonance-current = ζ atual = { $zeta }
resonance-drive = excitação r = { $ratio }
resonance-peak = pico
resonance-quadrature = −90° em r = 1
resonance-legend-width = largura de meia potência r₂ − r₁ = { $width }
resonance-legend-broad = |H| ≥ |H|max/√2 até r = { $upper }
resonance-legend-cutoff = corte de −3 dB em r = { $upper }
resonance-band-width = pontos de meia potência (|H| = |H|max/√2) em r = { $lower } e { $upper }: largura do pico r₂ − r₁ = { $width }
resonance-band-broad = |H| fica acima de |H|max/√2 de r = 0 até r = { $upper }: o pico não tem ponto inferior de meia potência, portanto sua largura de meia potência é indefinida
resonance-band-cutoff = |H| cai para 1/√2 do seu valor estático (−3 dB) no corte r = { $upper }; sem pico não há largura de meia potência
resonance-peak-at = pico de ressonância { $gain } em r = { $ratio }
resonance-no-peak = sem pico de ressonância (ζ ≥ 1/√2): |H| apenas decresce a partir de 1 em r = 0
resonance-describe-magnitude = { $view ->
        [db] Magnitude em dB para ζ = { $zeta }: { $peak }; { $band }. Na excitação r = { $drive }, a amplificação é { $gain }.
       *[linear] Magnitude para ζ = { $zeta }: { $peak }; { $band }. Na excitação r = { $drive }, a amplificação é { $gain }.
    }
resonance-describe-phase = Atraso de fase do deslocamento em relação à força para ζ = { $zeta }: 0° em baixa frequência, −90° em r = 1 para qualquer razão de amortecimento, tendendo a −180° acima da ressonância; quanto menor ζ, mais brusca a transição. Na excitação r = { $drive }, o atraso é { $degrees } ({ $radians } rad).
resonance-envelope = envoltória ±E(t)
resonance-steady-amplitude = amplitude em regime permanente ±X
resonance-describe-time-growing = Excitada a partir do repouso em r = { $ratio } (ω = { $omega }) durante { $span }: não há regime permanente; a amplitude cresce e chega a { $largest }.
resonance-describe-time = { $case ->
        [beats] Excitada a partir do repouso em r = { $ratio } (ω = { $omega }) durante { $span }: os movimentos livre e forçado batem com período { $period } (constante de tempo do decaimento { $tau }), tendendo à amplitude em regime permanente { $amplitude }, com atraso de { $lag } em relação à força. Maior afastamento mostrado: { $largest }.
        [build-up] Excitada a partir do repouso em r = { $ratio } (ω = { $omega }) durante { $span }: na ressonância a amplitude cresce em direção à amplitude em regime permanente { $amplitude } com constante de tempo 1/(ζωₙ) = { $tau }, com atraso de { $lag } em relação à força. Maior afastamento mostrado: { $largest }.
       *[transient] Excitada a partir do repouso em r = { $ratio } (ω = { $omega }) durante { $span }: após um transitório (constante de tempo { $tau }) ela se acomoda na amplitude em regime permanente { $amplitude }, com atraso de { $lag } em relação à força. Maior afastamento mostrado: { $largest }.
    }
resonance-fixed-base = base fixa
resonance-schematic = Massa sobre mola e amortecedor acima de uma base fixa, empurrada pela força F(t) = { $force } (seta acima da massa) em t = { $time }: deslocada { $displacement } do repouso.
resonance-beats-visible = visíveis
resonance-beats-no-free-oscillation = nenhum (sem oscilação livre, ζ ≥ 1)
resonance-beats-no-drive = nenhum (força constante)
resonance-beats-same-frequency = nenhum (excitação em ω_d)
resonance-beats-too-fast = nenhum (tão rápido quanto a oscilação)
resonance-beats-dies-out = nenhum (o movimento livre se extingue antes)
resonance-title = Ressonância forçada
resonance-summary = Uma massa de 1 kg sobre uma mola (k = ωₙ²·m) e um amortecedor (c = 2ζωₙ·m), em repouso, é excitada a partir de t = 0 por F(t) = F₀·cos(ωt). Em regime permanente, ela se move na frequência de excitação com amplitude |H(r)|·F₀/k, atrasada em relação à força pela fase de H, onde r = ω/ωₙ. Um amortecimento leve produz um pico alto e estreito perto de r = 1 (altura ≈ Q = 1/(2ζ)). Sua largura de meia potência, r₂ − r₁ entre as duas razões de frequência em que |H| = |H|max/√2, é ≈ 2ζ para amortecimento leve; acima de ζ ≈ 0,383 o ponto inferior chega a r = 0 e a largura fica indefinida, e acima de ζ = 1/√2 não há pico algum. Excitada exatamente na ressonância, a amplitude cresce ao longo de algumas constantes de tempo 1/(ζωₙ) sem batimento; excitada perto dela, os movimentos livre e forçado batem entre si até que a parte livre se extinga.
resonance-param-zeta = razão de amortecimento
resonance-param-r = razão de excitação ω/ωₙ
resonance-param-wn = frequência natural
resonance-param-F0 = amplitude da força
resonance-param-view = escala da magnitude
resonance-param-view-linear = |H| linear
resonance-param-view-db = decibéis 20·log₁₀|H|
resonance-readout-peak-gain = pico de ressonância |H|max
resonance-readout-peak-ratio = pico em r = ω/ωₙ
resonance-readout-Q = fator de qualidade Q = 1/(2ζ)
resonance-readout-peak-width = largura de meia potência do pico de |H| r₂ − r₁ (ζ < 0,383)
resonance-readout-gain-at-r = ganho |H(r)| na excitação
resonance-readout-phase-at-r = fase ∠H(r) na excitação
resonance-readout-amplitude = amplitude em regime permanente X = |H|·F₀/k
resonance-readout-beat-period = período de batimento 2π/|ω − ω_d| (enquanto há batimento)
resonance-readout-beats = batimentos em x(t)
resonance-plot-magnitude = Amplificação |H(r)|
resonance-plot-phase = Fase ∠H(r)
resonance-plot-time = Resposta a partir do repouso x(t)
resonance-preset-1 = Na ressonância, ζ = 0,05
resonance-preset-2 = Batimento perto da ressonância, r = 0,9
resonance-preset-3 = Sem pico, ζ ≈ 1/√2
resonance-preset-4 = Quase estático, r = 0,2
resonance-preset-5 = Isolamento, r = 3
