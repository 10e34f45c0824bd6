from http import HTTPStatus
from io import BytesIO
from typing import Any

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.error_out import ErrorOut
from ...models.plot_holding_request import PlotHoldingRequest
from ...types import File, Response


def _get_kwargs(
    *,
    body: PlotHoldingRequest,
) -> dict[str, Any]:
    headers: dict[str, Any] = {}

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/v1/plots/holding",
    }

    _kwargs["json"] = body.to_dict()

    headers["Content-Type"] = "application/json"

    _kwargs["headers"] = headers
    return _kwargs


def _parse_response(*, client: AuthenticatedClient | Client, response: httpx.Response) -> ErrorOut | File | None:
    if response.status_code == 200:
        response_200 = File(payload=BytesIO(response.content))

        return response_200

    if response.status_code == 401:
        response_401 = ErrorOut.from_dict(response.json())

        return response_401

    if response.status_code == 413:
        response_413 = ErrorOut.from_dict(response.json())

        return response_413

    if response.status_code == 422:
        response_422 = ErrorOut.from_dict(response.json())

        return response_422

    if response.status_code == 503:
        response_503 = ErrorOut.from_dict(response.json())

        return response_503

    if response.status_code == 504:
        response_504 = ErrorOut.from_dict(response.json())

        return response_504

    if client.raise_on_unexpected_status:
        raise errors.UnexpectedStatus(response.status_code, response.content)
    else:
        return None


def _build_response(*, client: AuthenticatedClient | Client, response: httpx.Response) -> Response[ErrorOut | File]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: PlotHoldingRequest,
) -> Response[ErrorOut | File]:
    """Figure: the chain under its weight as its base turns, and the least design holding it

     For `directions` gravity directions (base orientations) over a full turn (the chain's gravity
    magnitude, 9.81 without `gravity`): left, the rest configuration under its weight drawn with gravity
    down; right, the least total stiffness (`vary: [k]`) or preload tension (`vary: [L0]`) of
    `/v1/design/holding` holding it within `max_angle` with `margin`, against the base's elevation (a
    cross where none holds it), and the sag without a design. At most 60 segments. Answers `image/png`,
    or `image/svg+xml` with `"format": "svg"` (or, without `format`, an `Accept` header preferring
    `image/svg+xml`); `dpi` sets the PNG resolution.

    Args:
        body (PlotHoldingRequest): The chain under its weight as its base turns: its sagged shapes
            and the least design holding it.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorOut | File]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = client.get_httpx_client().request(
        **kwargs,
    )

    return _build_response(client=client, response=response)


def sync(
    *,
    client: AuthenticatedClient | Client,
    body: PlotHoldingRequest,
) -> ErrorOut | File | None:
    """Figure: the chain under its weight as its base turns, and the least design holding it

     For `directions` gravity directions (base orientations) over a full turn (the chain's gravity
    magnitude, 9.81 without `gravity`): left, the rest configuration under its weight drawn with gravity
    down; right, the least total stiffness (`vary: [k]`) or preload tension (`vary: [L0]`) of
    `/v1/design/holding` holding it within `max_angle` with `margin`, against the base's elevation (a
    cross where none holds it), and the sag without a design. At most 60 segments. Answers `image/png`,
    or `image/svg+xml` with `"format": "svg"` (or, without `format`, an `Accept` header preferring
    `image/svg+xml`); `dpi` sets the PNG resolution.

    Args:
        body (PlotHoldingRequest): The chain under its weight as its base turns: its sagged shapes
            and the least design holding it.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorOut | File
    """

    return sync_detailed(
        client=client,
        body=body,
    ).parsed


async def asyncio_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: PlotHoldingRequest,
) -> Response[ErrorOut | File]:
    """Figure: the chain under its weight as its base turns, and the least design holding it

     For `directions` gravity directions (base orientations) over a full turn (the chain's gravity
    magnitude, 9.81 without `gravity`): left, the rest configuration under its weight drawn with gravity
    down; right, the least total stiffness (`vary: [k]`) or preload tension (`vary: [L0]`) of
    `/v1/design/holding` holding it within `max_angle` with `margin`, against the base's elevation (a
    cross where none holds it), and the sag without a design. At most 60 segments. Answers `image/png`,
    or `image/svg+xml` with `"format": "svg"` (or, without `format`, an `Accept` header preferring
    `image/svg+xml`); `dpi` sets the PNG resolution.

    Args:
        body (PlotHoldingRequest): The chain under its weight as its base turns: its sagged shapes
            and the least design holding it.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorOut | File]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    *,
    client: AuthenticatedClient | Client,
    body: PlotHoldingRequest,
) -> ErrorOut | File | None:
    """Figure: the chain under its weight as its base turns, and the least design holding it

     For `directions` gravity directions (base orientations) over a full turn (the chain's gravity
    magnitude, 9.81 without `gravity`): left, the rest configuration under its weight drawn with gravity
    down; right, the least total stiffness (`vary: [k]`) or preload tension (`vary: [L0]`) of
    `/v1/design/holding` holding it within `max_angle` with `margin`, against the base's elevation (a
    cross where none holds it), and the sag without a design. At most 60 segments. Answers `image/png`,
    or `image/svg+xml` with `"format": "svg"` (or, without `format`, an `Accept` header preferring
    `image/svg+xml`); `dpi` sets the PNG resolution.

    Args:
        body (PlotHoldingRequest): The chain under its weight as its base turns: its sagged shapes
            and the least design holding it.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorOut | File
    """

    return (
        await asyncio_detailed(
            client=client,
            body=body,
        )
    ).parsed
